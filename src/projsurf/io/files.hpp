#pragma once
// projsurf/io/files: reading a file safely: InputError (the one error a front end prints), the
// input limits, UTF-8 text, image headers.
// The installed interface of the folder: include this header (docs/library.md).
#include "projsurf/io/files/errors.hpp"
#include "projsurf/io/files/files.hpp"
#include "projsurf/io/files/limits.hpp"
#include "projsurf/io/files/quiet_stderr.hpp"
#include "projsurf/io/files/utf8_text.hpp"

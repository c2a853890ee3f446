#pragma once
// The key table as declared: one key per setting field of DetectorConfig and the structs it
// nests, with the range and doc its field line gives (detection/detector_config.hpp says the
// form). Its definition is written at build time by scripts/config_keys.py from the headers
// (frontend/CMakeLists.txt); detector_config_keys.hpp is the table's interface.
#include <vector>

#include "projsurf/frontend/settings/detector_config_keys.hpp"

namespace projsurf::frontend {

template <typename T>
constexpr KeyType keyTypeOf() {
    if constexpr (std::is_same_v<T, bool>) return KeyType::Bool;
    if constexpr (std::is_same_v<T, int>) return KeyType::Int;
    if constexpr (std::is_same_v<T, unsigned>) return KeyType::Unsigned;
    if constexpr (std::is_same_v<T, double>) return KeyType::Double;
    if constexpr (std::is_same_v<T, std::vector<double>>) return KeyType::DoubleList;
    return KeyType::Word;
}

/// One key of the table: its field's path, the accessor of the field, its range and doc.
template <typename T>
ConfigKey declaredKey(const char *key, ConfigField<T> field, KeyRange range, const char *doc) {
    return ConfigKey{key, keyTypeOf<T>(), range, doc, ConfigAccess{field}};
}

/// Every declared setting, in the fields' order (each nested struct's keys together).
std::vector<ConfigKey> declaredConfigKeys();

}  // namespace projsurf::frontend

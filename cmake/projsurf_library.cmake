# projsurf_library(<folder>): the library of one folder under src/projsurf/, named
# projsurf_<folder>, with the ALIAS projsurf::<folder> (the name an installed package gives it,
# so a project builds the same way against a subdirectory or an installed tree).
function(projsurf_library folder)
  set(name projsurf_${folder})
  if(PROJSURF_SHARED_LIBS)
    add_library(${name} SHARED ${ARGN})
  else()
    add_library(${name} STATIC ${ARGN})
  endif()
  add_library(projsurf::${folder} ALIAS ${name})
  set_target_properties(${name} PROPERTIES
    EXPORT_NAME ${folder}
    VERSION ${PROJECT_VERSION}
    SOVERSION ${PROJECT_VERSION_MAJOR}.${PROJECT_VERSION_MINOR}
    POSITION_INDEPENDENT_CODE ON)  # static ones too: the Python module links them
  # Headers are included as "projsurf/<folder>/x.hpp".
  target_include_directories(${name} PUBLIC
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/src>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  # In a shared library GCC lets every exported function be replaced at load time, and so
  # neither inlines nor calls directly one exported function from another; projsurf's
  # functions are not meant to be interposed, so calls stay as in a static build.
  if(PROJSURF_SHARED_LIBS AND CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    target_compile_options(${name} PRIVATE -fno-semantic-interposition)
  endif()
  # Each library links everything it uses and nothing else: an undefined symbol (core calling
  # into sim, say) fails this library's link instead of a consumer's.
  if(PROJSURF_SHARED_LIBS AND CMAKE_SYSTEM_NAME STREQUAL "Linux")
    target_link_options(${name} PRIVATE -Wl,--no-undefined)
  endif()
endfunction()

# projsurf_install_headers(<folder>...): installs src/projsurf/<folder>/*.hpp.
function(projsurf_install_headers)
  if(NOT PROJSURF_INSTALL)
    return()
  endif()
  foreach(folder ${ARGN})
    install(DIRECTORY ${PROJECT_SOURCE_DIR}/src/projsurf/${folder}/
      DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/projsurf/${folder}
      COMPONENT devel FILES_MATCHING PATTERN "*.hpp")
  endforeach()
endfunction()

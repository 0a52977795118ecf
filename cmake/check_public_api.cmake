# cmake -P: the public API stays public (README "Public API").
#   -DSOURCE_DIR=<repository>  -DPUBLIC_LIST=<file with one vcg_ext-relative header a line>
#   [-DEXTRA_FRONT_END_FILES=<files checked like apps/>]
# Fails (listing every offence) when
#  - a public header includes (with quotes) a header that is not public, or does not exist;
#  - a file of apps/ or filter_hrsr/ (the CLI, the plugin and its host) includes (with quotes)
#    a header that is neither next to it nor public.
# A quoted include is resolved as the compiler does: next to the including file first, then
# from vcg_ext/ (the library's include directory).
cmake_minimum_required(VERSION 3.16)
file(STRINGS "${PUBLIC_LIST}" public)
set(offences "")
foreach(h IN LISTS public)
  if(NOT EXISTS "${SOURCE_DIR}/vcg_ext/${h}")
    string(APPEND offences "  public header vcg_ext/${h} does not exist\n")
  endif()
endforeach()

# check_file(FILE WHAT): every quoted include of FILE is next to it (in the front end's own
# folder, not reached through ../vcg_ext) or public; an include in angle brackets that names a
# header of vcg_ext/ must be public too.
function(check_file file what)
  file(STRINGS "${file}" lines REGEX "^[ \t]*#[ \t]*include[ \t]*[<\"]")
  get_filename_component(dir "${file}" DIRECTORY)
  foreach(line IN LISTS lines)
    string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*([<\"])([^>\"]+)[>\"].*" "\\1\\2" inc "${line}")
    string(SUBSTRING "${inc}" 0 1 quote)
    string(SUBSTRING "${inc}" 1 -1 inc)
    if(inc IN_LIST public)
      if(what STREQUAL "public header" AND quote STREQUAL "\"")
        get_filename_component(own "${dir}/${inc}" ABSOLUTE)
        # "x.h" from vcg_ext/io/ would be io/x.h, not the public x.h
        if(EXISTS "${own}" AND NOT own STREQUAL "${SOURCE_DIR}/vcg_ext/${inc}")
          string(APPEND offences "  ${file}: \"${inc}\" resolves to ${own}, not public\n")
        endif()
      endif()
      continue()
    endif()
    if(quote STREQUAL "<")
      if(EXISTS "${SOURCE_DIR}/vcg_ext/${inc}")
        string(APPEND offences "  ${file} (${what}): #include <${inc}> is not a public header\n")
      endif()
      continue() # a system or third-party header
    endif()
    get_filename_component(own "${dir}/${inc}" ABSOLUTE)
    string(FIND "${own}" "${SOURCE_DIR}/vcg_ext/" in_library)
    if(NOT what STREQUAL "public header" AND EXISTS "${own}" AND in_library EQUAL -1)
      continue() # the front end's own header
    endif()
    string(APPEND offences "  ${file} (${what}): #include \"${inc}\" is not a public header\n")
  endforeach()
  set(offences "${offences}" PARENT_SCOPE)
endfunction()

foreach(h IN LISTS public)
  if(EXISTS "${SOURCE_DIR}/vcg_ext/${h}")
    check_file("${SOURCE_DIR}/vcg_ext/${h}" "public header")
  endif()
endforeach()
file(GLOB_RECURSE front_ends "${SOURCE_DIR}/apps/*.h" "${SOURCE_DIR}/apps/*.cpp"
     "${SOURCE_DIR}/filter_hrsr/*.h" "${SOURCE_DIR}/filter_hrsr/*.cpp")
list(LENGTH front_ends n)
if(n LESS 20)
  message(FATAL_ERROR "only ${n} front-end files found under ${SOURCE_DIR}")
endif()
foreach(f IN LISTS front_ends EXTRA_FRONT_END_FILES)
  check_file("${f}" "front end")
endforeach()
if(offences)
  message(FATAL_ERROR "The public API leaks:\n${offences}")
endif()
list(LENGTH public np)
message(STATUS "public API: ${np} headers; ${n} front-end files include only them")

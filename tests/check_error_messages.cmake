# Fails when a GL error is recorded without a message: every record_error(GL_...) names the
# argument and the rule it broke (GL_KHR_debug, PINEDA_DEBUG=1).
# Usage: cmake -DROOT=<source dir> -P check_error_messages.cmake
set(found "")
foreach(dir state shader driver raster glapi)
  file(GLOB_RECURSE sources "${ROOT}/${dir}/*.cpp" "${ROOT}/${dir}/*.h" "${ROOT}/${dir}/*.py")
  foreach(source IN LISTS sources)
    file(STRINGS "${source}" lines REGEX "record_error\\(GL_[A-Z_]*\\)")
    foreach(line IN LISTS lines)
      file(RELATIVE_PATH name "${ROOT}" "${source}")
      string(STRIP "${line}" line)
      string(APPEND found "\n  ${name}: ${line}")
    endforeach()
  endforeach()
endforeach()
if(found)
  message(FATAL_ERROR "errors recorded without a message:${found}")
endif()

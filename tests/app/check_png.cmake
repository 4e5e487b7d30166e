# cmake -DFILE=... -P check_png.cmake: fails unless FILE exists and starts with the PNG signature.
if(NOT EXISTS "${FILE}")
  message(FATAL_ERROR "missing: ${FILE}")
endif()
file(READ "${FILE}" signature LIMIT 8 HEX)
if(NOT signature STREQUAL "89504e470d0a1a0a")
  message(FATAL_ERROR "not a PNG file: ${FILE}")
endif()
message(STATUS "ok: ${FILE}")

# Checks that FILE exists and holds a real picture rather than a blank frame: a flat-colour PNG
# of the window compresses to a few kilobytes, a rendered scene with text to far more.
#   cmake -DFILE=shot.png -DMIN_BYTES=30000 -P check_png.cmake
if(NOT EXISTS "${FILE}")
  message(FATAL_ERROR "${FILE} was not written")
endif()
file(SIZE "${FILE}" bytes)
if(bytes LESS MIN_BYTES)
  message(FATAL_ERROR "${FILE} has ${bytes} bytes: a blank image (expected >= ${MIN_BYTES})")
endif()
message(STATUS "ok: ${FILE} has ${bytes} bytes")

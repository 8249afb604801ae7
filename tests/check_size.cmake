# cmake -DFILE=path -DBYTES=n -P check_size.cmake: FILE exists and is exactly n bytes.
if(NOT EXISTS "${FILE}")
  message(FATAL_ERROR "${FILE} was not written")
endif()
file(SIZE "${FILE}" size)
if(NOT size EQUAL BYTES)
  message(FATAL_ERROR "${FILE} is ${size} bytes, expected ${BYTES}")
endif()

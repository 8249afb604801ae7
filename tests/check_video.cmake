# Checks an MP4's streams with ffprobe: one H.264 video stream of DURATION seconds (within one
# frame, 1 / FPS) and, with AUDIO=ON, one audio stream within 0.1 s of it (AAC frames are 1024
# samples, so the audio may overrun the cut by up to ~23 ms); with AUDIO=OFF no audio stream.
# Also fails on leftovers beside FILE (the temporary video or music WAV).
#   cmake -DFFPROBE=ffprobe -DFILE=out.mp4 -DDURATION=1 -DFPS=30 -DAUDIO=ON -P check_video.cmake
foreach(var FFPROBE FILE DURATION FPS AUDIO)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "check_video.cmake: -D${var}=... is required")
  endif()
endforeach()
if(NOT EXISTS "${FILE}")
  message(FATAL_ERROR "${FILE} was not written")
endif()
file(GLOB leftovers "${FILE}.tmp*")
if(leftovers)
  message(FATAL_ERROR "temporary files left beside ${FILE}: ${leftovers}")
endif()

execute_process(
  COMMAND ${FFPROBE} -v error -show_entries stream=codec_type,codec_name,duration -of csv=p=0
    "${FILE}"
  RESULT_VARIABLE rc
  OUTPUT_VARIABLE out
  ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "ffprobe failed on ${FILE} (${rc}):\n${err}")
endif()
message(STATUS "ffprobe:\n${out}")

# One line per stream, "codec_name,codec_type,duration" (ffprobe's field order).
string(STRIP "${out}" out)
string(REPLACE "\n" ";" lines "${out}")
set(videos 0)
set(audios 0)
foreach(line ${lines})
  string(REPLACE "," ";" fields "${line}")
  list(GET fields 0 codec)
  list(GET fields 1 type)
  list(GET fields 2 seconds)
  if(type STREQUAL "video")
    math(EXPR videos "${videos} + 1")
    set(video_codec ${codec})
    set(video_seconds ${seconds})
  elseif(type STREQUAL "audio")
    math(EXPR audios "${audios} + 1")
    set(audio_codec ${codec})
    set(audio_seconds ${seconds})
  endif()
endforeach()

if(AUDIO)
  set(expected_audios 1)
else()
  set(expected_audios 0)
endif()
if(NOT videos EQUAL 1 OR NOT audios EQUAL expected_audios)
  message(FATAL_ERROR "${FILE}: ${videos} video and ${audios} audio streams, expected 1 and "
    "${expected_audios}:\n${out}")
endif()
if(NOT video_codec STREQUAL "h264")
  message(FATAL_ERROR "${FILE}: video codec ${video_codec}, expected h264")
endif()

# |a - b| <= tolerance, in CMake's string arithmetic: math() is integer-only, so microseconds.
function(expect_near what actual expected tolerance)
  foreach(v actual expected tolerance)
    if(NOT "${${v}}" MATCHES "^[0-9]+(\\.[0-9]*)?$")
      message(FATAL_ERROR "${FILE}: ${what}: '${${v}}' is not a duration")
    endif()
    string(REGEX REPLACE "^([0-9]+).*$" "\\1" whole "${${v}}")
    set(frac "")
    if("${${v}}" MATCHES "\\.([0-9]*)$")
      set(frac "${CMAKE_MATCH_1}")
    endif()
    string(SUBSTRING "${frac}000000" 0 6 frac)
    math(EXPR us_${v} "${whole} * 1000000 + 1${frac} - 1000000")
  endforeach()
  math(EXPR diff "${us_actual} - ${us_expected}")
  if(diff LESS 0)
    math(EXPR diff "-${diff}")
  endif()
  if(diff GREATER us_tolerance)
    message(FATAL_ERROR "${FILE}: ${what} lasts ${actual} s, expected ${expected} s within "
      "${tolerance} s")
  endif()
  message(STATUS "ok: ${what} ${actual} s (expected ${expected} +- ${tolerance} s)")
endfunction()

# One frame, written as a decimal for expect_near (FPS is a whole number in these tests).
math(EXPR frame_us "1000000 / ${FPS}")
math(EXPR frame_whole "${frame_us} / 1000000")
math(EXPR frame_frac "${frame_us} % 1000000 + 1000000")
string(SUBSTRING "${frame_frac}" 1 6 frame_frac)
expect_near("video" "${video_seconds}" "${DURATION}" "${frame_whole}.${frame_frac}")
if(AUDIO)
  if(NOT audio_codec STREQUAL "aac")
    message(FATAL_ERROR "${FILE}: audio codec ${audio_codec}, expected aac")
  endif()
  expect_near("audio" "${audio_seconds}" "${video_seconds}" "0.1")
endif()

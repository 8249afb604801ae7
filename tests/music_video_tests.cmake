# `clothlab render --video` with a scene's [music]: the MP4 carries the music as AAC from frame 0,
# cut to the video's length; a scene without music gives a video stream alone. Each render is a
# fixture whose file check_video.cmake then probes with ffprobe. Included from
# tests/CMakeLists.txt after cli_tests.cmake (clothlab_cli_test).
find_program(FFMPEG ffmpeg)
find_program(FFPROBE ffprobe)
if(NOT FFMPEG OR NOT FFPROBE)
  message(STATUS "ffmpeg or ffprobe not found: the music video tests are skipped")
  return()
endif()

set(CLOTHLAB_VIDEO_OUT ${CMAKE_CURRENT_BINARY_DIR}/music_video)
file(MAKE_DIRECTORY ${CLOTHLAB_VIDEO_OUT})

# clothlab_video_test(NAME SCENE AUDIO FRAMES REGEX): renders 30 frames of SCENE at 30 fps into
# NAME_test.mp4 (summary matching REGEX), then checks 1 s of video and, with AUDIO=ON, as much
# audio.
# With FRAMES=ON the PNG frames are written too (--out), else the video alone.
function(clothlab_video_test name scene audio frames regex)
  set(video ${CMAKE_CURRENT_BINARY_DIR}/${name}_test.mp4)
  set(out)
  if(frames)
    set(out --out ${CLOTHLAB_VIDEO_OUT}/${name})
  endif()
  clothlab_cli_test(render.video_${name} 0 "${regex}"
    render ${scene} --frames 30 --fps 30 --size 160x120 ${out} --video ${video})
  add_test(NAME cli.render.video_${name}_streams
    COMMAND ${CMAKE_COMMAND} -DFFPROBE=${FFPROBE} -DFILE=${video} -DDURATION=1 -DFPS=30
      -DAUDIO=${audio} -P ${CMAKE_CURRENT_LIST_DIR}/check_video.cmake)
  set_tests_properties(cli.render.video_${name} PROPERTIES FIXTURES_SETUP video_${name}
    LABELS video)
  set_tests_properties(cli.render.video_${name}_streams PROPERTIES TIMEOUT 30
    FIXTURES_REQUIRED video_${name} LABELS video)
endfunction()

clothlab_video_test(dance ${PROJECT_SOURCE_DIR}/scenes/dance.toml ON ON
  "and [^ ]*dance_test\\.mp4 with music: generated drum track")
# The video alone: the summary names no frame directory.
clothlab_video_test(silent ${CLOTHLAB_DEFAULT_SCENE} OFF OFF
  "ms/frame writing; [^ ]*silent_test\\.mp4")

# --music-out: the scene's generated 40 s drum track as 16-bit mono WAV at 44.1 kHz (44-byte
# header + 40 * 44100 * 2 bytes), and a scene without music is refused.
set(CLOTHLAB_MUSIC_WAV ${CLOTHLAB_VIDEO_OUT}/dance_music.wav)
clothlab_cli_test(render.music_out 0 "render: 1 frames"
  render ${PROJECT_SOURCE_DIR}/scenes/dance.toml --frames 1 --size 64x48
  --out ${CLOTHLAB_VIDEO_OUT}/music_out --music-out ${CLOTHLAB_MUSIC_WAV})
add_test(NAME cli.render.music_out_size
  COMMAND ${CMAKE_COMMAND} -DFILE=${CLOTHLAB_MUSIC_WAV} -DBYTES=3528044
    -P ${CMAKE_CURRENT_LIST_DIR}/check_size.cmake)
set_tests_properties(cli.render.music_out PROPERTIES FIXTURES_SETUP music_out LABELS video)
set_tests_properties(cli.render.music_out_size PROPERTIES FIXTURES_REQUIRED music_out LABELS video)
clothlab_cli_test(render.music_out_without_music 1 "--music-out: the scene has no \\[music\\]"
  render ${CLOTHLAB_DEFAULT_SCENE} --frames 1 --size 64x48 --quiet
  --out ${CLOTHLAB_VIDEO_OUT}/no_music --music-out ${CLOTHLAB_VIDEO_OUT}/none.wav)

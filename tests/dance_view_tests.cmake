# The dance scene in the window (issue 9). Included from tests/CMakeLists.txt after
# cli_tests.cmake, whose clothlab_view_test (defined only where xvfb-run is found) runs
# `clothlab view` on ${CLOTHLAB_DEFAULT_SCENE}: here that is scenes/dance.toml, set inside a
# function so the scene that later files see is unchanged.
#
# No test opens an audio device (docs/contact.md section 4): CLOTHLAB_VIEW_NO_AUDIO=1 takes the path
# a machine without a device takes. The window must say so exactly once and run 30 frames of the
# dance, its Music panel drawn, to exit status 0.
function(clothlab_dance_view_tests)
  set(CLOTHLAB_DEFAULT_SCENE ${PROJECT_SOURCE_DIR}/scenes/dance.toml)
  set(silent "clothlab view: audio off \\(CLOTHLAB_VIEW_NO_AUDIO=1\\); running silently on the simulation clock\n")
  # CMake regexes have no look-ahead, so "exactly once" is the line with text on either side in
  # which "NO_AUDIO" does not occur (each of its letters followed by anything but the next).
  set(without "([^N]|N[^O]|NO[^_]|NO_[^A]|NO_A[^U]|NO_AU[^D]|NO_AUD[^I]|NO_AUDI[^O])*")
  clothlab_view_test(dance_silent "CLOTHLAB_VIEW_EXIT_AFTER_FRAMES=30|CLOTHLAB_VIEW_NO_AUDIO=1"
    "^${without}${silent}${without}$")
endfunction()

if(COMMAND clothlab_view_test)
  clothlab_dance_view_tests()
endif()

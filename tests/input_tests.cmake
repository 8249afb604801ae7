# Inputs that once got through (issue 21): each exact input must now exit 2 (bad input) with the
# key, file, line or argument and the reason, or exit 1 with one line (out of memory). Included
# from tests/CMakeLists.txt after cli_tests.cmake (it uses clothlab_cli_test).

set(CLOTHLAB_BAD_INPUTS ${CMAKE_CURRENT_LIST_DIR}/bad_inputs)
set(default ${PROJECT_SOURCE_DIR}/scenes/default.toml)
set(trace_out ${CMAKE_CURRENT_BINARY_DIR}/input_trace.csv)

# Finite doubles beyond a float: the key and the limit (they once wrote nan or inf to the CSV).
foreach(case "drag|forces.drag=1e39|forces\\.drag"
             "gravity|forces.gravity=[0,-1e39,0]|forces\\.gravity"
             "wind|forces.wind={velocity=[1e39,0,0]}|forces\\.wind\\.velocity"
             "size|cloth.size=[1e300,1e300]|cloth\\.size"
             "origin|cloth.origin=[1e308,1e308,1e308]|cloth\\.origin"
             "u_axis|cloth.u_axis=[1e200,0,0]|cloth\\.u_axis")
  string(REPLACE "|" ";" parts "${case}")
  list(GET parts 0 name)
  list(GET parts 1 set)
  list(GET parts 2 key)
  clothlab_cli_test(input.float_range.${name} 2 "${key}: must be at most 3\\.4e\\+38 in magnitude"
    trace ${default} --duration 0.1 --out ${trace_out} --set ${set})
endforeach()
clothlab_cli_test(input.damping_beyond_float 2 "springs\\.damping: must be at most 3\\.4e\\+38"
  trace ${PROJECT_SOURCE_DIR}/scenes/skirt.toml --duration 0.1 --out ${trace_out}
  --set springs.damping=1e39)
clothlab_cli_test(input.gravity_beyond_float_implicit 2 "forces\\.gravity: must be at most"
  trace ${default} --duration 0.1 --out ${trace_out} --set forces.gravity=[0,-1e39,0]
  --set solver.integrator="implicit_euler")

# Values inside the range that build a state the float solver cannot hold.
clothlab_cli_test(input.built_forces_overflow 2
  "default\\.toml:[0-9]+:[0-9]+: cloth: the force on vertex 0 of the built cloth is not finite in float"
  trace ${default} --duration 0.1 --out ${trace_out} --set cloth.size=[1e30,1e30])
clothlab_cli_test(input.vertex_mass_underflow 2
  "cloth\\.mass: gives vertex masses of 0 kg in float"
  check ${default} --set cloth.mass=1e-44)
# A huge axis is normalised to a unit vector, not to zero ([1e30, 0, 0] is within the range).
clothlab_cli_test(input.huge_axis_normalised 0 "ok \\(1 cloth"
  check ${default} --set cloth.u_axis=[1e30,0,0])
clothlab_cli_test(input.huge_plane_normal 0 "ok \\(1 cloth"
  check ${PROJECT_SOURCE_DIR}/scenes/drop_sphere.toml --set colliders[1].normal=[0,1e30,0])

# Step counts: overflowing (dt 1e-20 for 1 s), an automatic step of 0, and a run shorter than one
# step all say so before running; none writes a one-row trace.
clothlab_cli_test(input.step_count_overflow 2
  "--duration 1 at solver\\.dt = 1e-20 s is more steps than a trace may take \\(1e\\+20 steps"
  trace ${default} --duration 1 --out ${trace_out} --set solver.dt=1e-20)
clothlab_cli_test(input.auto_step_vanishes 2 "solver\\.dt = [0-9.e+-]+ s \\(auto\\) is more steps"
  trace ${default} --duration 1 --out ${trace_out} --set forces.drag=1e38)
clothlab_cli_test(input.shorter_than_one_step 2 "is shorter than one step"
  trace ${default} --duration 0.0001 --out ${trace_out} --set solver.dt=0.001)
# A valid but enormous run says its size within its first second and shows progress; one beyond
# a day is refused with the estimate.
clothlab_cli_test(input.enormous_run_refused 2
  "steps of 1e-09 s would take about [0-9.]+ (h|days) here \\([0-9.]+ ms/step over the first [0-9]+ steps; at most 24 h\\)"
  trace ${PROJECT_SOURCE_DIR}/scenes/skirt.toml --duration 100 --out ${trace_out}
  --set solver.dt=1e-9)

# Files: OBJ coordinates, degenerate and fan meshes, sounds, devices as scenes.
function(clothlab_bad_input file line key message)
  clothlab_cli_test(input.${file} 2 "${file}\\.toml:${line}:[0-9]+: ${key}: [^\n]*${message}"
    check ${CLOTHLAB_BAD_INPUTS}/${file}.toml)
endfunction()
clothlab_bad_input(cloth_text_coordinate 4 "cloth\\.file"
  "text_coordinate\\.obj: line 3: vertex x coordinate \"a\" is not a number")
clothlab_bad_input(cloth_nan_coordinate 4 "cloth\\.file"
  "nan_coordinate\\.obj: line 2: vertex y coordinate \"nan\" is not finite")
clothlab_bad_input(cloth_huge_exponent_zero 5 "cloth\\.file"
  "huge_exponent_zero\\.obj: line 3: vertex z coordinate is not finite as the OBJ reader reads it")
clothlab_bad_input(cloth_missing_coordinate 4 "cloth\\.file"
  "missing_coordinate\\.obj: line 3: vertex has no z coordinate")
clothlab_bad_input(cloth_overflow_coordinate 4 "cloth\\.file"
  "overflow_coordinate\\.obj: line 3: vertex z coordinate 1e39 is beyond the largest float")
clothlab_bad_input(collider_overflow 7 "colliders.0.\\.file"
  "overflow_coordinate\\.obj: line 3: vertex z coordinate 1e39")
clothlab_bad_input(cloth_collinear_face 4 "cloth\\.file"
  "collinear_face\\.obj: line 6: the face \\(vertices 1, 2, 3\\) has zero area")
clothlab_bad_input(cloth_fan 4 "cloth\\.file"
  "fan\\.obj: OBJ vertex 1 has 200 edges; a mesh cloth may have at most 128")
clothlab_bad_input(music_inf_sample 6 "music\\.file" "inf_sample\\.wav': sample 4000 \\(t = 0\\.5")
clothlab_bad_input(music_rate_100hz 6 "music\\.file"
  "rate_100hz\\.wav': a sample rate of 100 Hz is too low for the beat tracker")
clothlab_bad_input(music_rate_2147483647hz 7 "music\\.file"
  "rate_2147483647hz\\.wav': a sample rate of 2147483647 Hz is beyond the highest in use")
# The decoder's warnings come back as one line inside the message, after the file's name.
clothlab_bad_input(music_id3_garbage 6 "music\\.file"
  "id3_garbage\\.mp3': not a sound file libsndfile can decode \\(decoder: [^\n]*\\)\n?$")
clothlab_cli_test(input.dev_zero 2 "/dev/zero: is not a regular file" check /dev/zero)

# Memory: a scene that cannot fit is refused with both figures; an allocation that fails anyway
# is one line and exit 1 (prlimit, from util-linux, caps the address space: 1.2 GB holds the 1.2 GB
# estimate of a 1000 x 1000 sheet, but not the thread stacks and allocator arenas beside it).
clothlab_cli_test(input.two_huge_cloths 2
  "the scene's cloths have 32000000 vertices up to this one; at most 16000000"
  check ${PROJECT_SOURCE_DIR}/scenes/two_sheets.toml --set cloth[0].resolution=[4000,4000]
  --set cloth[1].resolution=[4000,4000])
# check answers at once for any size: before building it says both estimates, and a build
# estimated at over a minute is refused with them unless --force (a 4000 x 4000 sheet, refused by
# the build estimate, or by memory first on a machine that cannot hold it; seconds either way).
clothlab_cli_test(input.huge_grid_is_estimated 2
  "cloth\\.resolution: the scene needs about [0-9.]+ GB and [0-9]+ s to build \\(16000000 vertices, [a-z_]+, float\\)"
  check ${default} --set cloth.resolution=[4000,4000])
set_tests_properties(cli.input.huge_grid_is_estimated PROPERTIES TIMEOUT 30)
clothlab_cli_test(input.check_says_its_estimates 0
  "default\\.toml: needs about [0-9.e-]+ GB and [0-9.e-]+ s to build \\(1024 vertices, [a-z_]+, float\\)\n[^\n]*: ok"
  check ${default} --force)
find_program(CLOTHLAB_PRLIMIT prlimit)
# clothlab_limited_test(NAME BYTES RC REGEX ARGS...): `clothlab ARGS...` with its address space
# capped at BYTES. Not under the sanitizers: ASan reserves terabytes of address space.
function(clothlab_limited_test name bytes rc regex)
  if(NOT CLOTHLAB_PRLIMIT OR CLOTHLAB_SANITIZE)
    return()
  endif()
  string(JOIN "|" args ${ARGN})
  add_test(NAME cli.${name}
    COMMAND ${CMAKE_COMMAND} "-DCOMMAND=${CLOTHLAB_PRLIMIT}|--as=${bytes}|$<TARGET_FILE:clothlab>|${args}"
      "-DEXPECT_RC=${rc}" "-DEXPECT_REGEX=${regex}" -P ${CMAKE_CURRENT_LIST_DIR}/expect_exit.cmake)
  set_tests_properties(cli.${name} PROPERTIES TIMEOUT 60 ENVIRONMENT "${CLOTHLAB_TEST_ENVIRONMENT}")
endfunction()
clothlab_limited_test(input.memory_refused 1200000000 2
  "cloth\\.resolution: the scene needs about 5\\.[0-9]+ GB and [0-9]+ s to build \\(1000000 vertices, local_global, float\\) and this machine can give 1\\.2 GB"
  check ${default} --set cloth.resolution=[1000,1000] --set solver.integrator="local_global")
clothlab_limited_test(input.out_of_memory_is_one_line 1210000000 1
  "^[^\n]*: needs about [^\n]*\nclothlab check: out of memory[^\n]*\n$"
  check ${default} --set cloth.resolution=[1000,1000])

# Killed runs leave no temporary file (SIGTERM and SIGINT, trace and render --video).
add_test(NAME cli.input.killed_runs_leave_no_temporary_files
  COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/kill_test.sh $<TARGET_FILE:clothlab> ${default}
    ${CMAKE_CURRENT_BINARY_DIR}/kill_test)
set_tests_properties(cli.input.killed_runs_leave_no_temporary_files
  PROPERTIES TIMEOUT 120 ENVIRONMENT "${CLOTHLAB_GL_TEST_ENVIRONMENT}")

# Found by the fuzz pass: an automatic xpbd step of 1.7e9 substeps ran for hours in one step. The
# automatic count now follows the cloth's size, not its stiffness, and stops at kXpbdMaxSubsteps
# (sim/stability/step_limit.hpp): this 24 x 16 cloth takes the floor of 10.
clothlab_cli_test(input.xpbd_stiff_substeps 0 "xpbd, dt = 0\\.0166667 s \\(auto\\) in 10 substeps"
  check ${CLOTHLAB_BAD_INPUTS}/xpbd_stiff_substeps.toml)

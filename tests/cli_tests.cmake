# Command-line tests: `clothlab check` on bad scenes and bad --set values must exit with status
# exactly 2 and print a message naming the file, line and key (docs/design.md, "Command line").
# Included from tests/CMakeLists.txt; each test runs expect_exit.cmake.

set(CLOTHLAB_BAD_SCENES ${CMAKE_CURRENT_LIST_DIR}/bad_scenes)
set(CLOTHLAB_DEFAULT_SCENE ${PROJECT_SOURCE_DIR}/scenes/default.toml)

# clothlab_cli_test(NAME RC REGEX ARGS...): runs `clothlab ARGS...`, expects status RC and output
# matching REGEX. ARGS must not contain '|' (expect_exit.cmake's separator).
function(clothlab_cli_test name rc regex)
  clothlab_env_test(${name} "" ${rc} "${regex}" ${ARGN})
endfunction()

# clothlab_env_test(NAME ENV RC REGEX ARGS...): the same with the environment changed first by
# ENV, `cmake -E env` arguments joined by '|' (e.g. "--unset=DISPLAY"); empty: unchanged.
function(clothlab_env_test name env rc regex)
  set(environment "${CLOTHLAB_TEST_ENVIRONMENT}")
  if(name MATCHES "^(render|view)\\." OR name MATCHES "^(bench\\.backends|trace\\.gpu)")  # GL
    set(environment "${CLOTHLAB_GL_TEST_ENVIRONMENT}")
  endif()
  string(JOIN "|" args ${ARGN})
  set(program "$<TARGET_FILE:clothlab>")
  if(NOT env STREQUAL "")
    set(program "${CMAKE_COMMAND}|-E|env|${env}|${program}")
  endif()
  add_test(NAME cli.${name}
    COMMAND ${CMAKE_COMMAND}
      "-DCOMMAND=${program}|${args}"
      "-DEXPECT_RC=${rc}"
      "-DEXPECT_REGEX=${regex}"
      -P ${CMAKE_CURRENT_LIST_DIR}/expect_exit.cmake)
  set_tests_properties(cli.${name} PROPERTIES TIMEOUT 60 ENVIRONMENT "${environment}")
endfunction()

# clothlab_bad_scene(FILE LINE KEY_REGEX MESSAGE_REGEX): `clothlab check bad_scenes/FILE.toml`
# must exit 2 with "FILE.toml:LINE:COL: KEY: MESSAGE".
function(clothlab_bad_scene file line key message)
  clothlab_cli_test(check.${file} 2 "${file}\\.toml:${line}:[0-9]+: ${key}: ${message}"
    check ${CLOTHLAB_BAD_SCENES}/${file}.toml)
endfunction()

# The program itself: --version, help, and a mistyped subcommand named with the list.
clothlab_cli_test(version 0 "^clothlab 0\\.1\\.0" --version)
clothlab_cli_test(help 0 "Subcommands:.*check.*params.*trace.*render.*view.*bench.*tune" help)
clothlab_cli_test(unknown_subcommand 2
  "unknown subcommand \"frobnicate\"; the subcommands are check, params, trace, render, view, bench, tune, help"
  frobnicate)
clothlab_bad_scene(syntax_error 6 "TOML syntax error" "")
clothlab_bad_scene(unknown_top_key 5 "physics" "unknown top-level key")
clothlab_bad_scene(unknown_nested_key 6 "solver\\.dtt" "unknown key")
clothlab_bad_scene(wrong_type 4 "cloth\\.mass" "expected a number, got string")
clothlab_bad_scene(float_resolution 3 "cloth\\.resolution.0." "expected an integer, got float")
clothlab_bad_scene(non_finite 6 "springs\\.stiffness" "must be finite")
clothlab_bad_scene(negative_dt 6 "solver\\.dt" "must be > 0")
clothlab_bad_scene(zero_mass 4 "cloth\\.mass" "must be > 0")
clothlab_bad_scene(pin_outside 4 "cloth\\.pins.1." "pin .8, 0. is outside the 8 x 8 grid")
clothlab_bad_scene(mesh_pin_int_min 6 "cloth\\.pins.1."
  "pin -2147483648 is not an OBJ vertex number \\(they count from 1\\)")
clothlab_bad_scene(duplicate_pin 4 "cloth\\.pins.2." "pin .0, 0. is listed twice")
clothlab_bad_scene(all_pinned 4 "cloth\\.pins" "every vertex is pinned")
clothlab_bad_scene(unknown_integrator 6 "solver\\.integrator" "unknown integrator .leapfrog.")
clothlab_bad_scene(unknown_backend 6 "solver\\.backend" ".*unknown backend \"cuda\" \\(valid: cpu, gpu, transform_feedback\\)")
clothlab_bad_scene(transform_feedback_verlet 6 "solver\\.integrator"
  "solver\\.backend = \"transform_feedback\" steps symplectic_euler, explicit_euler and seed_hack, not verlet")
clothlab_bad_scene(collider_radius 8 "colliders.0.\\.radius" "must be > 0")
clothlab_bad_scene(collider_friction 8 "colliders.0.\\.friction\\.static" "must be >= 0")
clothlab_bad_scene(collider_obj_missing 6 "colliders.0.\\.file" "[^\n]*no_such_chair\\.obj: no such OBJ file")
clothlab_bad_scene(skewed_axes 5 "cloth\\.v_axis" "must be orthogonal")
clothlab_bad_scene(wind_without_velocity 6 "forces\\.wind\\.velocity" "missing")
clothlab_bad_scene(trace_outside 7 "trace\\.vertices.1." "vertex .8, 2. is outside")
clothlab_bad_scene(multi_cloth_bad_mass 9 "cloth.1.\\.mass" "must be > 0")

clothlab_cli_test(check.missing_file 2 "no_such_scene\\.toml: cannot open scene file"
  check ${CLOTHLAB_BAD_SCENES}/no_such_scene.toml)

# --set overrides on the good default scene go through the same checks; the message names the
# --set argument instead of a file position.
function(clothlab_bad_set name regex)
  clothlab_cli_test(set.${name} 2 "${regex}" check ${CLOTHLAB_DEFAULT_SCENE} ${ARGN})
endfunction()

clothlab_bad_set(negative_dt "--set solver\\.dt=-1: solver\\.dt: must be > 0 \\(got -1\\)"
  --set solver.dt=-1)
clothlab_bad_set(dt_not_a_number "--set solver\\.dt=fast: solver\\.dt: expected a number"
  --set solver.dt=fast)
clothlab_bad_set(nan_drag "--set forces\\.drag=nan: forces\\.drag: must be finite"
  --set forces.drag=nan)
clothlab_bad_set(unknown_key "--set solver\\.dtt=0\\.1: solver\\.dtt: unknown key"
  --set solver.dtt=0.1)
clothlab_bad_set(unknown_table "--set physics\\.dt=1: physics: unknown top-level key"
  --set physics.dt=1)
clothlab_bad_set(music_missing "--set music\\.file=no_such\\.wav: music\\.file: [^\n]*no_such\\.wav"
  --set music.file=no_such.wav)
clothlab_bad_set(unknown_integrator "solver\\.integrator: unknown integrator .rk5."
  --set solver.integrator=rk5)
clothlab_bad_set(resolution_type "cloth\\.resolution: expected an array"
  --set cloth.resolution=8)
clothlab_bad_set(index_single_cloth
  "--set cloth.1.\\.mass=2: cloth: is a single table in this scene, not an array of tables: write cloth\\.mass .a scene with several writes each as ..cloth..."
  --set cloth[1].mass=2)
clothlab_bad_set(no_equals "--set solver\\.dt: expected key\\.path=value" --set solver.dt)
clothlab_bad_set(empty_path "--set =3: empty key path" --set =3)
# A later bad override is caught even when an earlier one is fine.
clothlab_bad_set(second_override "--set solver\\.threads=-2: solver\\.threads: must be between"
  --set solver.dt=0.0005 --set solver.threads=-2)

# The good cases: the default scene and valid overrides exit 0.
clothlab_cli_test(check.default_scene 0 "" check ${CLOTHLAB_DEFAULT_SCENE})
clothlab_cli_test(set.valid 0 "" check ${CLOTHLAB_DEFAULT_SCENE}
  --set solver.integrator=rk4 --set solver.dt=0.0002 --set "solver.precision=double")

# `clothlab trace`: a good run prints the one-line summary and writes the CSV; a diverging run
# exits 1 naming step, time, vertex and quantity plus the command that replays it; bad
# arguments exit 2 naming the argument.
set(CLOTHLAB_TRACE_OUT ${CMAKE_CURRENT_BINARY_DIR}/cli_trace)
file(MAKE_DIRECTORY ${CLOTHLAB_TRACE_OUT})
clothlab_cli_test(trace.default 0
  "trace: 0\\.49972 s simulated in 806 steps of 0\\.00062 s \\(auto\\), .* ms/step .*final energy .* J"
  trace ${CLOTHLAB_DEFAULT_SCENE} --duration 0.5 --out ${CLOTHLAB_TRACE_OUT}/default.csv)
# --quiet: nothing at all on success (a script's own output stays clean); errors still print.
clothlab_cli_test(trace.quiet 0 "<nothing>"
  trace ${CLOTHLAB_DEFAULT_SCENE} --duration 0.05 --out ${CLOTHLAB_TRACE_OUT}/quiet.csv --quiet)
clothlab_cli_test(trace.quiet_still_says_divergence 1 "simulation diverged at step"
  trace ${CLOTHLAB_DEFAULT_SCENE} --duration 0.1 --out ${CLOTHLAB_TRACE_OUT}/quiet_diverged.csv
  --quiet --set solver.dt=0.01)
# Every command waits passively at OpenMP barriers, after a 1000-spin wait, when the user set no
# policy (issue 23: with OpenMP's spinning default a loaded machine made a trace 66x slower), and
# the summary says so;
# threads = 0 gives the 32x32 default scene one thread (below kParallelMinVertices).
clothlab_env_test(trace.passive_by_default "--unset=OMP_WAIT_POLICY" 0
  "\\(symplectic_euler, float, CPU, 1 thread\\(s\\), passive wait after 1000 spins, 1024 vertices\\)"
  trace ${CLOTHLAB_DEFAULT_SCENE} --duration 0.01 --out ${CLOTHLAB_TRACE_OUT}/passive.csv)
clothlab_env_test(trace.user_wait_policy_kept "OMP_WAIT_POLICY=active" 0 "2 thread\\(s\\), active wait"
  trace ${CLOTHLAB_DEFAULT_SCENE} --duration 0.01 --out ${CLOTHLAB_TRACE_OUT}/active.csv
  --set solver.threads=2)
# An --out that cannot be written is refused before the run, with the reason (exit 2).
clothlab_cli_test(trace.out_in_missing_directory 2
  "clothlab trace: --out: cannot write '/nonexistent_dir/t\\.csv': no such directory \\('/nonexistent_dir'\\)"
  trace ${CLOTHLAB_DEFAULT_SCENE} --duration 0.1 --out /nonexistent_dir/t.csv)
clothlab_cli_test(trace.diverges 1
  "diverged at step [0-9]+ \\(t = [0-9.e-]+ s\\): vertex \\(cloth 0, i [0-9]+, j [0-9]+\\), .*replay with: clothlab trace .*--set 'solver.dt=0.002'.*a step of 0\\.002 s is above symplectic_euler's stability limit on this scene \\(0\\.000786 s\\); solver\\.dt = \"auto\" takes 0\\.00062 s"
  trace ${CLOTHLAB_DEFAULT_SCENE} --duration 1 --out ${CLOTHLAB_TRACE_OUT}/diverged.csv
  --set solver.dt=0.002)
# A lattice stretched beyond the scene's energy scale in two steps, before the velocities grow:
# the summary's energy check catches it at the last step (exit 1, no file), where it once wrote a
# trace ending at 4.8e11 J.
clothlab_cli_test(trace.diverges_in_elastic_energy 1
  "diverged at step 2 \\(t = 0\\.002 s\\): vertex \\(cloth 0, i [0-9]+, j [0-9]+\\), (total|elastic) energy [0-9.e+]+ J \\(elastic [0-9.e+]+ J\\) exceeds 1000 x the scene's energy scale"
  trace ${CLOTHLAB_DEFAULT_SCENE} --duration 0.002 --out ${CLOTHLAB_TRACE_OUT}/stretched.csv
  --set solver.integrator=explicit_euler --set springs.stiffness=1e9 --set solver.dt=0.001)
# Values that would break something downstream are refused under the key the user wrote: a gust
# period too short for the noise (was: a non-finite force at the file's first line), the
# mannequin's friction (was: the first part's key), vertices too close for float springs (was:
# an infinite spring stiffness).
clothlab_cli_test(check.gust_period_denormal 2
  "--set forces\\.wind\\.gust_period=5e-324: forces\\.wind\\.gust_period: must be >= 1e-06"
  check ${CLOTHLAB_DEFAULT_SCENE} --set forces.wind.gust_period=5e-324)
clothlab_cli_test(check.mannequin_friction 2
  "--set mannequin\\.friction=-1: mannequin\\.friction\\.static: must be >= 0 \\(got -1\\)"
  check ${PROJECT_SOURCE_DIR}/scenes/dance.toml --set mannequin.friction=-1)
clothlab_cli_test(check.tube_radius_tiny 2
  "cloth\\.radius: puts neighbouring vertices [0-9.e-]+ m apart round the first ring; at least 1e-06 m is needed"
  check ${PROJECT_SOURCE_DIR}/scenes/skirt.toml --set "cloth.radius=[1e-320,0.4]")
clothlab_cli_test(check.grid_size_tiny 2
  "cloth\\.size: puts neighbouring vertices [0-9.e-]+ m apart along u"
  check ${CLOTHLAB_DEFAULT_SCENE} --set "cloth.size=[1e-9,1]")
# The same lattice traced with its energy every step: the row of step 2 is the one refused (the
# kinetic check alone would stop the run a step later).
clothlab_cli_test(trace.diverges_in_a_rows_energy 1
  "diverged at step 2 \\(t = 0\\.002 s\\): .*(total|elastic) energy [0-9.e+]+ J \\(elastic"
  trace ${CLOTHLAB_DEFAULT_SCENE} --duration 0.01 --out ${CLOTHLAB_TRACE_OUT}/stretched_rows.csv
  --set solver.integrator=explicit_euler --set springs.stiffness=1e9 --set solver.dt=0.001
  "--set=trace.fields=[\"energy\"]" --set trace.every=1)
# check knows the explicit methods' limits: a fixed step above one is valid input (exit 0) but
# said, with dt = "auto"'s step; below it nothing is said.
clothlab_cli_test(check.step_above_the_limit 0
  "default\\.toml: warning: a step of 0\\.01 s is above symplectic_euler's stability limit on this scene \\(0\\.000786 s\\); solver\\.dt = \"auto\" takes 0\\.00062 s"
  check ${CLOTHLAB_DEFAULT_SCENE} --set solver.dt=0.01)
clothlab_cli_test(check.no_stable_step 0
  "warning: explicit_euler has no stable step on this scene \\(it needs damping\\)"
  check ${CLOTHLAB_DEFAULT_SCENE} --set solver.integrator=explicit_euler --set springs.damping=0
  --set forces.drag=0 --set solver.dt=0.0001)
clothlab_cli_test(check.step_below_the_limit 0 "dt = 0\\.0005 s\\)[^a-z]*$"
  check ${CLOTHLAB_DEFAULT_SCENE} --set solver.dt=0.0005)
# Every explicit method run at 10x its stable step on the default scene (limits from
# `clothlab bench --suite stability`'s theory for this scene: explicit Euler 1.05e-4 s, symplectic
# Euler 6.26e-4, seed_hack 4.62e-4, verlet 5.43e-4, rk4 1.07e-3) is caught: exit 1, a message
# naming step, time and vertex, and no file.
foreach(case "explicit_euler:0.00105" "symplectic_euler:0.00626" "seed_hack:0.00462"
             "verlet:0.00543" "rk4:0.0107")
  string(REPLACE ":" ";" parts ${case})
  list(GET parts 0 kind)
  list(GET parts 1 dt)
  clothlab_cli_test(trace.diverges_10x.${kind} 1
    "diverged at step [0-9]+ \\(t = [0-9.e-]+ s\\): vertex \\(cloth 0, i [0-9]+, j [0-9]+\\)"
    trace ${CLOTHLAB_DEFAULT_SCENE} --duration 1 --out ${CLOTHLAB_TRACE_OUT}/diverged_${kind}.csv
    --set solver.integrator=${kind} --set solver.dt=${dt})
endforeach()
# dt = "auto" picks the step from the scene's highest frequency (0.8 x the method's limit, two
# significant digits: 0.0005 s for symplectic Euler above, 4.3e-4 s for Verlet, whose limit is
# 5.43e-4 s); the iterative methods report their work.
clothlab_cli_test(trace.auto_dt 0 "steps of 0\\.00052 s \\(auto\\)"
  trace ${CLOTHLAB_DEFAULT_SCENE} --duration 0.05 --out ${CLOTHLAB_TRACE_OUT}/auto.csv
  --set solver.integrator=verlet)
foreach(kind implicit_euler xpbd local_global vbd bdf2)
  clothlab_cli_test(trace.large_step.${kind} 0
    "trace: 0\\.5 s simulated .*solver: [0-9.e+]+ iterations per substep"
    trace ${CLOTHLAB_DEFAULT_SCENE} --duration 0.5 --out ${CLOTHLAB_TRACE_OUT}/${kind}.csv
    --set solver.integrator=${kind} --set solver.dt=auto)
endforeach()
clothlab_cli_test(set.bad_substeps 2 "--set solver.substeps=0: solver.substeps: must be at least 1, or \"auto\""
  check ${CLOTHLAB_DEFAULT_SCENE} --set solver.substeps=0)
clothlab_cli_test(set.bad_cg_tolerance 2 "solver.cg_tolerance: must be between 0 \\(automatic\\) and 1, exclusive of 1"
  check ${CLOTHLAB_DEFAULT_SCENE} --set solver.cg_tolerance=2)
clothlab_cli_test(set.bad_dt_word 2 "solver.dt: expected a number of seconds or \"auto\""
  check ${CLOTHLAB_DEFAULT_SCENE} --set solver.dt=fastest)

# `clothlab tune` (docs/tuning.md): on the default scene at 8 x 8 to 0.25 s it prints the table,
# the cheapest setting within the tolerance as --set lines and TOML, and writes the CSV (a row per
# setting and sample time) and the plot; bad arguments are bad input.
clothlab_cli_test(tune.small 0
  "at 0\\.0667 s.*reference: rk4 \\(double\\).*\\* .*xpbd.*within 20 mm RMS up to 0\\.25 s: .*--set solver\\.integrator=.*\\[solver\\].integrator = .*wrote .*tune_small\\.csv and .*tune_small\\.png"
  tune ${CLOTHLAB_DEFAULT_SCENE} --set cloth.resolution=[8,8] --set cloth.pins=[[0,0],[7,0]]
  --set trace.vertices=[[4,7]]
  --duration 0.25 --tolerance 0.02 --threads 1 --quiet --out ${CLOTHLAB_TRACE_OUT}/tune_small.csv)
add_test(NAME cli.tune.small_csv
  COMMAND ${CMAKE_COMMAND} -DFILE=${CLOTHLAB_TRACE_OUT}/tune_small.csv
    "-DHEADER_REGEX=^setting,family,time \\(s\\),rms error \\(m\\),max error \\(m\\),energy drift \\(J\\),wall per simulated s \\(s\\),frontier,status,set$"
    "-DROW_REGEX=^(\"[^\"]*\"|[^,]+),(reference|explicit|implicit|constraints|descent),"
    -DMIN_ROWS=40
    -P ${CMAKE_CURRENT_LIST_DIR}/check_csv.cmake)
add_test(NAME cli.tune.small_png
  COMMAND ${CMAKE_COMMAND} -DFILE=${CLOTHLAB_TRACE_OUT}/tune_small.png -DMIN_BYTES=10000
    -P ${CMAKE_CURRENT_LIST_DIR}/check_png.cmake)
set_tests_properties(cli.tune.small PROPERTIES FIXTURES_SETUP tune_small)
set_tests_properties(cli.tune.small_csv cli.tune.small_png PROPERTIES FIXTURES_REQUIRED tune_small)
clothlab_cli_test(tune.zero_duration 2 "clothlab tune: --duration: Value 0 not in range"
  tune ${CLOTHLAB_DEFAULT_SCENE} --duration 0)
clothlab_cli_test(tune.negative_tolerance 2 "clothlab tune: --tolerance: Value -1 not in range"
  tune ${CLOTHLAB_DEFAULT_SCENE} --tolerance -1)
clothlab_cli_test(tune.bad_scene 2 "clothlab tune: .*negative_dt\\.toml:6:[0-9]+: solver\\.dt: must be > 0"
  tune ${CLOTHLAB_BAD_SCENES}/negative_dt.toml)
# --scheduler runs the settings on a Dask cluster through the Python module
# (tests/python/test_tune.py runs one); an address that is not one is bad input, and a build
# without the module (the sanitizers') says so.
if(CLOTHLAB_PYTHON)
  clothlab_cli_test(tune.scheduler_not_an_address 2
    "clothlab tune: --scheduler nohost: not a scheduler's address"
    tune ${CLOTHLAB_DEFAULT_SCENE} --scheduler nohost --out ${CLOTHLAB_TRACE_OUT}/tune_nohost.csv)
else()
  clothlab_cli_test(tune.scheduler_without_python 2
    "clothlab tune: --scheduler: this build has no Python module"
    tune ${CLOTHLAB_DEFAULT_SCENE} --scheduler nohost --out ${CLOTHLAB_TRACE_OUT}/tune_nohost.csv)
endif()

# solver.tolerance (docs/tuning.md, "A tolerance in the scene"): the first trace tunes the 8 x 8
# scene to 1 s and keeps the table in the cache folder, the second reads it from there, and a
# tolerance below the reference's own error is bad input at its key.
set(CLOTHLAB_TUNE_CACHE "CLOTHLAB_CACHE_DIR=${CLOTHLAB_TRACE_OUT}/tune_cache")
set(CLOTHLAB_SMALL_DEFAULT --set cloth.resolution=[8,8] --set cloth.pins=[[0,0],[7,0]]
  --set trace.vertices=[[4,7]])
clothlab_env_test(trace.tolerance_tunes "${CLOTHLAB_TUNE_CACHE}" 0
  "solver\\.tolerance 20 mm: .* within 20 mm to 1 s"
  trace ${CLOTHLAB_DEFAULT_SCENE} ${CLOTHLAB_SMALL_DEFAULT} --set solver.tolerance=0.02
  --duration 0.1 --out ${CLOTHLAB_TRACE_OUT}/tolerance.csv)
clothlab_env_test(trace.tolerance_cached "${CLOTHLAB_TUNE_CACHE}" 0
  "solver\\.tolerance 5 mm: .* within 5 mm to 1 s.*\\(from the cache\\)"
  trace ${CLOTHLAB_DEFAULT_SCENE} ${CLOTHLAB_SMALL_DEFAULT} --set solver.tolerance=0.005
  --duration 0.1 --out ${CLOTHLAB_TRACE_OUT}/tolerance_cached.csv)
clothlab_env_test(trace.tolerance_too_small "${CLOTHLAB_TUNE_CACHE}" 2
  "solver\\.tolerance: 1e-09 mm is below the reference's own error to 1 s on this scene"
  trace ${CLOTHLAB_DEFAULT_SCENE} ${CLOTHLAB_SMALL_DEFAULT} --set solver.tolerance=1e-12
  --duration 0.1 --out ${CLOTHLAB_TRACE_OUT}/tolerance_small.csv)
set_tests_properties(cli.trace.tolerance_tunes PROPERTIES FIXTURES_SETUP tune_cache)
set_tests_properties(cli.trace.tolerance_cached cli.trace.tolerance_too_small PROPERTIES
  FIXTURES_REQUIRED tune_cache)

# `clothlab bench`: a reduced suite writes its tables; a bad suite name is bad input.
clothlab_cli_test(bench.stability_quick 0 "Largest stable dt.*wrote .*stability\\.csv.*wrote .*stability_stress\\.csv"
  bench --suite stability --quick --out ${CLOTHLAB_TRACE_OUT}/bench/stability.csv)
# Issue 54's suite, reduced to 32^2 and 48^2: the error against RK4 is the small-steps tests' (3.5
# mm at 0.2 s with xpbd's defaults).
clothlab_cli_test(bench.realtime_quick 0
  "accuracy sheet at 32x32.*xpbd defaults +10 +3\\.5 .*xpbd x20 +20 .*by sheet size.*48x48 +2304 +10 .*wrote .*realtime_sizes\\.csv"
  bench --suite realtime --quick --threads 2 --out ${CLOTHLAB_TRACE_OUT}/bench/realtime.csv)
# solver.backend = "gpu" from the command line: trace and render step the cloth on the GPU and say
# so; a scene the GPU cannot run says why in one line and runs on the CPU.
clothlab_cli_test(trace.gpu_backend 0 "ms/step \\(symplectic_euler, float, GPU, .*wrote"
  trace ${CLOTHLAB_DEFAULT_SCENE} --duration 0.05 --out ${CLOTHLAB_TRACE_OUT}/trace_gpu.csv
  --set solver.backend=gpu)
clothlab_cli_test(trace.gpu_backend_rk4 0
  "clothlab trace: solver\\.backend = \"gpu\": the GPU step runs symplectic_euler and verlet, not rk4; the cloth steps on the CPU.*float, CPU,"
  trace ${CLOTHLAB_DEFAULT_SCENE} --duration 0.02 --out ${CLOTHLAB_TRACE_OUT}/trace_gpu_rk4.csv
  --set solver.backend=gpu --set solver.integrator=rk4)
# Without an OpenGL context (here: EGL finds no vendor library) the GPU choice says so in one
# line and the CPU runs the scene.
clothlab_env_test(trace.gpu_without_gl "__EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent.json" 0
  "clothlab trace: solver\\.backend = \"gpu\": EGL [^\n]*; the cloth steps on the CPU\n.*float, CPU,"
  trace ${CLOTHLAB_DEFAULT_SCENE} --duration 0.01 --out ${CLOTHLAB_TRACE_OUT}/trace_gpu_no_gl.csv
  --set solver.backend=gpu)
# solver.backend = "transform_feedback": the step as a vertex shader with transform feedback;
# what it cannot run is refused naming the key (exit 2), never run on another path.
clothlab_cli_test(trace.gpu_transform_feedback 0
  "ms/step \\(symplectic_euler, float, GPU transform feedback, .*wrote"
  trace ${CLOTHLAB_DEFAULT_SCENE} --duration 0.05 --out ${CLOTHLAB_TRACE_OUT}/trace_tf.csv
  --set solver.backend=transform_feedback)
clothlab_cli_test(trace.gpu_transform_feedback_shape 2
  "skirt\\.toml:7:[0-9]+: cloth\\.shape: solver\\.backend = \"transform_feedback\" draws grid cloths only, not a tube"
  trace ${PROJECT_SOURCE_DIR}/scenes/skirt.toml --duration 0.01
  --out ${CLOTHLAB_TRACE_OUT}/trace_tf_tube.csv --set solver.backend=transform_feedback
  --set solver.integrator=symplectic_euler)
clothlab_cli_test(render.transform_feedback 0 "steps of [0-9.]+ s on the GPU transform feedback\\)"
  render ${CLOTHLAB_DEFAULT_SCENE} --frames 2 --size 160x90
  --out ${CLOTHLAB_TRACE_OUT}/render_tf --set solver.backend=transform_feedback)
clothlab_cli_test(render.gpu_backend 0 "steps of [0-9.]+ s on the GPU\\)"
  render ${CLOTHLAB_DEFAULT_SCENE} --frames 2 --size 160x90
  --out ${CLOTHLAB_TRACE_OUT}/render_gpu --set solver.backend=gpu)
# The GPU backend against the CPU solver (an OpenGL context: EGL on llvmpipe in CI).
clothlab_cli_test(bench.backends_quick 0 "CPU, GPU compute and GPU transform-feedback backends.*gpu .*32x32.*transform_feedback .*32x32.*wrote .*backends\\.csv"
  bench --suite backends --quick --out ${CLOTHLAB_TRACE_OUT}/bench/backends.csv)
# An existing directory as --out takes the one suite's files (it was renamed onto: an error).
file(MAKE_DIRECTORY ${CLOTHLAB_TRACE_OUT}/bench_directory)
clothlab_cli_test(bench.largestep_quick_into_directory 0
  "Cheapest run within each error level.*Large steps.*--quick leaves out: k0 = 1e4.*wrote [^\n]*/bench_directory/largestep\\.csv"
  bench --suite largestep --quick --out ${CLOTHLAB_TRACE_OUT}/bench_directory)
clothlab_cli_test(bench.bad_suite 2 "--suite: speed not in"
  bench --suite speed)
# The views suite renders headless (EGL, so the GL tests' environment): a reduced run prints the
# GL renderer and every variant, and after turning everything off again no diagnostic state is
# held (the timing verdict beside it is not checked: ctest -j shares the cores).
clothlab_cli_test(bench.views_quick 0
  "Scientific view costs per frame: .* on [^,]+,.*everything on .*all off again \\(after everything on\\)[ 0-9.]+ no .*wrote .*views\\.csv"
  bench --suite views --quick --out ${CLOTHLAB_TRACE_OUT}/bench/views.csv)
set_tests_properties(cli.bench.views_quick PROPERTIES ENVIRONMENT "${CLOTHLAB_GL_TEST_ENVIRONMENT}")
clothlab_cli_test(bench.rendering_quick 0
  "Render cost per headless frame, quality full: .*mode 3, every optional pass off.*mode 7 light depth map.*quality fast: .*mode 7 light depth map.*wrote .*rendering\\.csv"
  bench --suite rendering --quick --out ${CLOTHLAB_TRACE_OUT}/bench/rendering.csv)
set_tests_properties(cli.bench.rendering_quick PROPERTIES ENVIRONMENT "${CLOTHLAB_GL_TEST_ENVIRONMENT}")

clothlab_cli_test(trace.bad_duration 2 "--duration: must be a finite number"
  trace ${CLOTHLAB_DEFAULT_SCENE} --duration -1 --out ${CLOTHLAB_TRACE_OUT}/bad.csv)
clothlab_cli_test(trace.nan_duration 2 "--duration: must be a finite number"
  trace ${CLOTHLAB_DEFAULT_SCENE} --duration nan --out ${CLOTHLAB_TRACE_OUT}/bad.csv)
clothlab_cli_test(trace.missing_out 2 "--out is required"
  trace ${CLOTHLAB_DEFAULT_SCENE} --duration 1)
clothlab_cli_test(trace.bad_set 2 "--set cloth\\.resolution=\\[0,4\\]: cloth\\.resolution"
  trace ${CLOTHLAB_DEFAULT_SCENE} --duration 1 --out ${CLOTHLAB_TRACE_OUT}/bad.csv
  --set cloth.resolution=[0,4])

# `clothlab render` and `clothlab view` (headless EGL on CI). They open OpenGL, so under the
# sanitizers they run with the GL tests' environment (tests/CMakeLists.txt); render re-executes
# itself with a passive OpenMP wait policy.
clothlab_cli_test(render.small 0
  "render: 3 frames of 64x48 \\(mode 1, quality (full|fast) \\(auto\\)\\) on .*ms/frame simulation .*ms/frame rendering"
  render ${CLOTHLAB_DEFAULT_SCENE} --frames 3 --size 64x48 --mode 1
  --out ${CLOTHLAB_TRACE_OUT}/render_small)
clothlab_cli_test(render.quality_set 0 "quality full\\) on "
  render ${CLOTHLAB_DEFAULT_SCENE} --frames 2 --size 64x48 --set render.quality=\"full\"
  --out ${CLOTHLAB_TRACE_OUT}/render_full)
# The large sheet at fast quality: drawn coarser, and the summary says how (docs/rendering.md
# section 9).
clothlab_cli_test(render.large_sheet_coarser 0
  "quality fast, cloth drawn at every [0-9]+(nd|th) vertex\\) on "
  render ${PROJECT_SOURCE_DIR}/scenes/large_sheet.toml --frames 1 --size 320x180
  --set render.quality=\"fast\" --out ${CLOTHLAB_TRACE_OUT}/render_large_sheet)
clothlab_cli_test(render.nothing_to_write 2 "nothing to write: give --out DIR"
  render ${CLOTHLAB_DEFAULT_SCENE} --frames 2)
clothlab_cli_test(render.bad_size 2 "--size: must be WxH"
  render ${CLOTHLAB_DEFAULT_SCENE} --size 64 --out ${CLOTHLAB_TRACE_OUT}/render_bad)
clothlab_cli_test(render.bad_fps 2
  "clothlab render: --fps: must be between 1 and 10000, got 0 \\(clothlab render --help\\)"
  render ${CLOTHLAB_DEFAULT_SCENE} --fps 0 --out ${CLOTHLAB_TRACE_OUT}/render_bad)
clothlab_cli_test(render.help_defaults 0 "--frames INT:1 to 1000000=60[^0-9].*--size TEXT:WxH=1280x720 .*--fps FLOAT:1 to 10000=60 "
  render --help)
clothlab_cli_test(bench.help_default_suite 0 "--suite TEXT:.*=all " bench --help)
clothlab_cli_test(view.help_keys 0 "Keys in the window:.*F12.*screenshot" view --help)
clothlab_cli_test(render.bad_mode 2 "--mode: must be between 1 and 7, got 8"
  render ${CLOTHLAB_DEFAULT_SCENE} --mode 8 --out ${CLOTHLAB_TRACE_OUT}/render_bad)
clothlab_cli_test(render.bad_scene_mode 2 "--set render\\.mode=0.*render\\.mode: must be a display mode from 1 to 7"
  render ${CLOTHLAB_DEFAULT_SCENE} --set render.mode=0 --out ${CLOTHLAB_TRACE_OUT}/render_bad)
clothlab_cli_test(render.bad_shadows 2 "render\\.shadows: unknown shadow filter .vsm."
  render ${CLOTHLAB_DEFAULT_SCENE} --set render.shadows=vsm --out ${CLOTHLAB_TRACE_OUT}/render_bad)
# --probe prints one JSON line with the field under the pixel (centre of the default view: cloth).
# Each test renders into its own directory: under ctest -j two renders of frame_00000.png into
# one directory raced (one's rename found the other's temporary file gone).
clothlab_cli_test(render.probe 0
  "{\"field\": \"velocity\", \"pixel\": \\[80, 60\\], \"value\": \\[[-0-9.e+]+, [-0-9.e+]+, [-0-9.e+]+\\], \"magnitude\": [0-9.e+-]+, \"vertex\": \\[[0-9]+, [0-9]+\\], \"vertex_value\": \\[[-0-9.e+]+, [-0-9.e+]+, [-0-9.e+]+\\]}"
  render ${CLOTHLAB_DEFAULT_SCENE} --frames 2 --size 160x120 --quiet
  --out ${CLOTHLAB_TRACE_OUT}/render_probe --probe 80,60 --field velocity)
clothlab_cli_test(render.quiet 0 "<nothing>"
  render ${CLOTHLAB_DEFAULT_SCENE} --frames 2 --size 64x48 --quiet --out ${CLOTHLAB_TRACE_OUT}/render_quiet)
# With --quiet the probe's JSON is the whole output.
clothlab_cli_test(render.probe_sky 0
  "^{\"field\": \"force\", \"pixel\": \\[0, 0\\], \"value\": null, \"magnitude\": null, \"vertex\": null, \"vertex_value\": null}"
  render ${CLOTHLAB_DEFAULT_SCENE} --frames 1 --size 160x120 --quiet
  --out ${CLOTHLAB_TRACE_OUT}/render_probe_sky --probe 0,0)
clothlab_cli_test(render.probe_outside 2 "--probe 160,60: must be PX,PY, a pixel inside the 160x120 image"
  render ${CLOTHLAB_DEFAULT_SCENE} --size 160x120 --out ${CLOTHLAB_TRACE_OUT}/render_bad
  --probe 160,60)
clothlab_cli_test(render.probe_not_a_pixel 2 "--probe abc: must be PX,PY"
  render ${CLOTHLAB_DEFAULT_SCENE} --size 160x120 --out ${CLOTHLAB_TRACE_OUT}/render_bad
  --probe abc)
clothlab_cli_test(render.bad_field 2 "--field: density not in"
  render ${CLOTHLAB_DEFAULT_SCENE} --out ${CLOTHLAB_TRACE_OUT}/render_bad --probe 1,1
  --field density)
# A file's directory must exist and be writable: refused when the command line is read, as for
# trace, not after the frames by ffmpeg.
clothlab_cli_test(render.video_into_missing_directory 2
  "clothlab render: --video: cannot write '/nonexistent-dir/x\\.mp4': no such directory \\('/nonexistent-dir'\\)"
  render ${CLOTHLAB_DEFAULT_SCENE} --frames 2 --size 32x32 --quiet
  --out ${CLOTHLAB_TRACE_OUT}/render_video --video /nonexistent-dir/x.mp4)
clothlab_cli_test(render.music_into_missing_directory 2
  "clothlab render: --music-out: cannot write '/nonexistent-dir/m\\.wav': no such directory"
  render ${PROJECT_SOURCE_DIR}/scenes/dance.toml --frames 1 --size 32x32 --quiet
  --out ${CLOTHLAB_TRACE_OUT}/render_music --music-out /nonexistent-dir/m.wav)
clothlab_cli_test(render.video_name_too_long 2
  "clothlab render: --video: cannot use '[n]+\\.mp4': File name too long"
  render ${CLOTHLAB_DEFAULT_SCENE} --frames 2 --size 32x32 --quiet
  --video nnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnn.mp4)
# A video whose end ffmpeg cannot write is refused (exit 1) and nothing is kept, where ffmpeg
# itself exits 0 and leaves an MP4 without its index (the moov atom, written last). A file-size
# limit stands in for a full disk: with SIGXFSZ ignored, writes past it fail as on ENOSPC.
set(CLOTHLAB_VIDEO_LIMIT_DIR ${CMAKE_CURRENT_BINARY_DIR}/video_limit)
file(MAKE_DIRECTORY ${CLOTHLAB_VIDEO_LIMIT_DIR})
add_test(NAME cli.render.video_cut_short
  COMMAND sh -c "cd '${CLOTHLAB_VIDEO_LIMIT_DIR}' && rm -f v.mp4* && trap '' XFSZ && ulimit -f 20 && '$<TARGET_FILE:clothlab>' render '${CLOTHLAB_DEFAULT_SCENE}' --frames 30 --size 320x240 --video v.mp4 --quiet; echo \"exit status $?\"; echo left: $(ls)")
set_tests_properties(cli.render.video_cut_short PROPERTIES TIMEOUT 60
  ENVIRONMENT "${CLOTHLAB_GL_TEST_ENVIRONMENT}"
  PASS_REGULAR_EXPRESSION "ffmpeg wrote an incomplete video for 'v\\.mp4' .*nothing was kept\nexit status 1\nleft:\n")
# The same on a real full file system for every writer (trace, video, PNG frames, music): a small
# tmpfs in a private mount namespace, skipped with the reason where none can be mounted.
add_test(NAME cli.output.full_disk
  COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/full_disk_test.sh $<TARGET_FILE:clothlab>
    ${PROJECT_SOURCE_DIR}/scenes ${CMAKE_CURRENT_BINARY_DIR}/full_disk)
set_tests_properties(cli.output.full_disk PROPERTIES TIMEOUT 120
  ENVIRONMENT "${CLOTHLAB_GL_TEST_ENVIRONMENT}" SKIP_REGULAR_EXPRESSION "SKIP: ")
# Scientific views headless: colour by a scalar, arrows, force source; bad values name the option.
clothlab_cli_test(render.views 0 "render: 2 frames of 96x72 .*colour by strain \\[-?[0-9.e+-]+, [0-9.e+-]+\\].* [0-9]+ force arrows"
  render ${CLOTHLAB_DEFAULT_SCENE} --frames 2 --size 96x72 --color-by strain
  --colormap coolwarm --range symmetric --arrows force,normals --force-source springs
  --arrow-stride 4 --arrow-scale log --out ${CLOTHLAB_TRACE_OUT}/render_views)
clothlab_cli_test(render.bad_range 2 "--range: must be auto, symmetric or MIN,MAX with MIN < MAX"
  render ${CLOTHLAB_DEFAULT_SCENE} --color-by height --range 2,1 --out ${CLOTHLAB_TRACE_OUT}/render_bad)
clothlab_cli_test(render.bad_arrows 2 "--arrows: velocity not in"
  render ${CLOTHLAB_DEFAULT_SCENE} --arrows velocity --out ${CLOTHLAB_TRACE_OUT}/render_bad)
clothlab_cli_test(render.bad_color_by 2 "--color-by: pressure not in"
  render ${CLOTHLAB_DEFAULT_SCENE} --color-by pressure --out ${CLOTHLAB_TRACE_OUT}/render_bad)
clothlab_cli_test(render.bad_force_source 2 "--force-source: inertia not in"
  render ${CLOTHLAB_DEFAULT_SCENE} --arrows force --force-source inertia --out ${CLOTHLAB_TRACE_OUT}/render_bad)
# Without a display, view says so in one line, suggests render and exits 1 (DISPLAY is removed
# so the test never opens a window on a developer's desktop).
clothlab_env_test(view.no_display "--unset=DISPLAY|--unset=WAYLAND_DISPLAY" 1
  "clothlab view: no display available.*clothlab render" view)

# The window itself, under a virtual X display (Xvfb, installed by scripts/deps): it opens,
# takes every display mode and the main keys, quits by itself after 40 frames with status 0
# and writes a screenshot of its last frame, which must be a real picture. The test hooks are
# described in apps/view/view_app.hpp.
find_program(XVFB_RUN xvfb-run)
if(XVFB_RUN)
  set(CLOTHLAB_VIEW_SHOT ${CLOTHLAB_TRACE_OUT}/view_last_frame.png)
  add_test(NAME cli.view.window
    COMMAND ${CMAKE_COMMAND}
      "-DCOMMAND=${CMAKE_COMMAND}|-E|env|--unset=WAYLAND_DISPLAY|CLOTHLAB_VIEW_EXIT_AFTER_FRAMES=40|CLOTHLAB_VIEW_SCREENSHOT=${CLOTHLAB_VIEW_SHOT}|CLOTHLAB_VIEW_KEYS=2,,1,,3,,C,,C,,P,,W,,M,,H,,.,,Space,,8,,,,9,,,,0|CLOTHLAB_VIEW_CURSOR=640,400|${XVFB_RUN}|-a|-s|-screen 0 1024x768x24|$<TARGET_FILE:clothlab>|view|${CLOTHLAB_DEFAULT_SCENE}"
      "-DEXPECT_RC=0"
      -P ${CMAKE_CURRENT_LIST_DIR}/expect_exit.cmake)
  add_test(NAME cli.view.window_screenshot
    COMMAND ${CMAKE_COMMAND} -DFILE=${CLOTHLAB_VIEW_SHOT} -DMIN_BYTES=30000
      -P ${CMAKE_CURRENT_LIST_DIR}/check_png.cmake)
  set_tests_properties(cli.view.window PROPERTIES TIMEOUT 120 FIXTURES_SETUP view_window
    ENVIRONMENT "${CLOTHLAB_GL_TEST_ENVIRONMENT}")
  set_tests_properties(cli.view.window_screenshot PROPERTIES FIXTURES_REQUIRED view_window)
  # Probing, pinning and recording: 8 turns the force probe on, a click at the cursor (on the
  # cloth, centred right of the panel) pins it to the vertex there, Record starts on the next frame and F / N show the arrows; the window
  # closes by itself while recording, which must finish the CSV (complete, every row whole) for
  # the pinned vertex, not the scene's default traced vertex (16, 31).
  set(CLOTHLAB_VIEW_RECORD ${CLOTHLAB_TRACE_OUT}/view_record.csv)
  add_test(NAME cli.view.record_pinned
    COMMAND ${CMAKE_COMMAND}
      "-DCOMMAND=${CMAKE_COMMAND}|-E|env|--unset=WAYLAND_DISPLAY|CLOTHLAB_VIEW_EXIT_AFTER_FRAMES=30|CLOTHLAB_VIEW_KEYS=8,,,,F,N|CLOTHLAB_VIEW_CURSOR=830,400|CLOTHLAB_VIEW_CLICK=3|CLOTHLAB_VIEW_RECORD=${CLOTHLAB_VIEW_RECORD}|${XVFB_RUN}|-a|-s|-screen 0 1280x800x24|$<TARGET_FILE:clothlab>|view|${CLOTHLAB_DEFAULT_SCENE}"
      "-DEXPECT_RC=0"
      "-DEXPECT_REGEX=clothlab view: recorded [1-9][0-9]* rows to .*view_record.csv"
      -P ${CMAKE_CURRENT_LIST_DIR}/expect_exit.cmake)
  set(csv_number "-?[0-9][0-9.e+-]*")
  add_test(NAME cli.view.record_pinned_csv
    COMMAND ${CMAKE_COMMAND} -DFILE=${CLOTHLAB_VIEW_RECORD}
      "-DHEADER_REGEX=^step,time,vertex_i,vertex_j,px,py,pz,vx,vy,vz,fx,fy,fz,kinetic,elastic,gravity,total$"
      "-DROW_REGEX=^[0-9]+,${csv_number},[0-9]+,[0-9]+(,${csv_number})+$"
      "-DFORBID_REGEX=^[0-9]+,[^,]+,16,31,"
      -DMIN_ROWS=2
      -P ${CMAKE_CURRENT_LIST_DIR}/check_csv.cmake)
  set_tests_properties(cli.view.record_pinned PROPERTIES TIMEOUT 120 FIXTURES_SETUP view_record
    ENVIRONMENT "${CLOTHLAB_GL_TEST_ENVIRONMENT}")
  set_tests_properties(cli.view.record_pinned_csv PROPERTIES FIXTURES_REQUIRED view_record)
  # clothlab_view_test(NAME HOOKS REGEX): `clothlab view` on the default scene in a 1280x800
  # virtual screen with the test hooks HOOKS (VAR=value entries joined by '|'), which must exit
  # 0 and print a line matching REGEX.
  # Arguments after REGEX follow the scene on the command line.
  function(clothlab_view_test name hooks regex)
    set(extra "")
    foreach(arg ${ARGN})
      string(APPEND extra "|${arg}")
    endforeach()
    add_test(NAME cli.view.${name}
      COMMAND ${CMAKE_COMMAND}
        "-DCOMMAND=${CMAKE_COMMAND}|-E|env|--unset=WAYLAND_DISPLAY|${hooks}|${XVFB_RUN}|-a|-s|-screen 0 1280x800x24|$<TARGET_FILE:clothlab>|view|${CLOTHLAB_DEFAULT_SCENE}${extra}"
        "-DEXPECT_RC=0"
        "-DEXPECT_REGEX=${regex}"
        -P ${CMAKE_CURRENT_LIST_DIR}/expect_exit.cmake)
    set_tests_properties(cli.view.${name} PROPERTIES TIMEOUT 120
      ENVIRONMENT "${CLOTHLAB_GL_TEST_ENVIRONMENT}")
  endfunction()
  # + twice: four copies of the cloth side by side, stepped on the GPU; - halves them again (at
  # one copy it does nothing). The hook spells the keys out (Plus, Minus): CMake lists mangle
  # some characters.
  clothlab_view_test(gpu_copies
    "CLOTHLAB_VIEW_EXIT_AFTER_FRAMES=12|CLOTHLAB_VIEW_KEYS=Minus,,Plus,,Plus,,,,Minus,,Plus"
    "clothlab view: 4 copies \\(4096 vertices\\).*clothlab view: 2 copies \\(2048 vertices\\).*frames: .*\\(4 copies, GPU backend, 4096 vertices, scene drawn at [0-9]+x[0-9]+, drawn by "
    --set solver.backend=gpu)
  # A cheap solver keeps real time from the first frames on: the new solver's cost is timed on
  # its first steps (probe_step_cost), not guessed from one step while a frame's time is dropped
  # (was 86-91 % over a 30-frame run). Release build only (CMakePresets.json): under the
  # sanitizers the solver needs more than its share of a frame.
  clothlab_view_test(real_time "CLOTHLAB_VIEW_EXIT_AFTER_FRAMES=30"
    "29 frames: .* (9[5-9]|10[0-9]) % of real time simulated \\(1 copy, CPU backend")
  # E turns the error view on: a reference run beside the shown one, the cloth coloured by the
  # distance; P restarts the comparison from the pushed state; the window's summary counts the
  # comparisons made (docs/tuning.md, "The error in the window").
  set(CLOTHLAB_VIEW_ERROR_SHOT ${CLOTHLAB_TRACE_OUT}/view_error_view.png)
  clothlab_view_test(error_view
    "CLOTHLAB_VIEW_EXIT_AFTER_FRAMES=40|CLOTHLAB_VIEW_SCREENSHOT=${CLOTHLAB_VIEW_ERROR_SHOT}|CLOTHLAB_VIEW_KEYS=,E,,,,,,,,,,,,,,,,,,,P"
    "error view: reference rk4 \\(double\\), step [0-9.]+ ms, comparing from t = 0.00 s.*error view: comparing from t = [0-9.]+ s \\(push\\).*error view: [1-9][0-9]* comparisons to t = [0-9.]+ s")
  add_test(NAME cli.view.error_view_screenshot
    COMMAND ${CMAKE_COMMAND} -DFILE=${CLOTHLAB_VIEW_ERROR_SHOT} -DMIN_BYTES=30000
      -P ${CMAKE_CURRENT_LIST_DIR}/check_png.cmake)
  set_tests_properties(cli.view.error_view PROPERTIES FIXTURES_SETUP view_error)
  set_tests_properties(cli.view.error_view_screenshot PROPERTIES FIXTURES_REQUIRED view_error)
  # D drops the cloth: the solver lets go of its pins (the window says so only when it has).
  clothlab_view_test(drop_key "CLOTHLAB_VIEW_EXIT_AFTER_FRAMES=6|CLOTHLAB_VIEW_KEYS=,,D"
    "clothlab view: pins released")
  # Ctrl + left drag pulls the cloth: a scripted drag from the middle of the part the open panel
  # leaves free (the hanging cloth, centred there by the camera's lens shift) 200 points up grabs the vertex there, and at the release that vertex is nearer the
  # drag's last target than it was when grabbed.
  clothlab_view_test(grab_drag
    "CLOTHLAB_VIEW_EXIT_AFTER_FRAMES=17|CLOTHLAB_VIEW_DRAG=830,400,830,200,3,16"
    "clothlab view: grab: released vertex [0-9]+ [^\n]*\\(closer\\)")
  # The scene picker opens another scene in the running window (its colliders with it); a
  # file that cannot be built leaves the running scene and says why.
  clothlab_view_test(scene_picker
    "CLOTHLAB_VIEW_EXIT_AFTER_FRAMES=5|CLOTHLAB_VIEW_OPEN=2:${PROJECT_SOURCE_DIR}/scenes/drop_sphere.toml"
    "clothlab view: opened drop_sphere\\.toml \\(1024 vertices, 2 colliders\\)")
  clothlab_view_test(scene_picker_bad
    "CLOTHLAB_VIEW_EXIT_AFTER_FRAMES=5|CLOTHLAB_VIEW_OPEN=2:${CLOTHLAB_BAD_SCENES}/collider_radius.toml"
    "clothlab view: not opened: [^\n]*collider_radius\\.toml:8:[0-9]+: colliders.0.\\.radius: must be > 0")
else()
  message(WARNING "xvfb-run not found: the window test is not run (scripts/deps installs it)")
endif()

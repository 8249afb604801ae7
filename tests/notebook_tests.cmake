# Notebook tests: the built clothlab makes small inputs (a 0.5 s trace, the --quick accuracy and
# stability tables) as fixtures, then scripts/notebooks executes each notebook headless on them
# (Debian's Python and nbconvert) and every figure it must write is checked to be a real picture.
# The inputs: a 0.5 s trace and the --quick accuracy, stability and largestep tables.
# Included from tests/CMakeLists.txt after cli_tests.cmake (uses clothlab_cli_test). About 25 s
# on 2 cores. Without nbconvert (scripts/deps installs it) the notebook tests fail and say so.

if(NOT COMMAND clothlab_cli_test)
  message(WARNING "notebook tests need tests/cli_tests.cmake (clothlab_cli_test): not registered")
  return()
endif()
if(CLOTHLAB_SANITIZE)
  # The notebooks are Python; the sanitizers would only slow down making their inputs.
  message(STATUS "notebook tests: not in the sanitizer build (the release build runs them)")
  return()
endif()

set(CLOTHLAB_NOTEBOOK_INPUTS ${CMAKE_CURRENT_BINARY_DIR}/notebook_inputs)
set(CLOTHLAB_NOTEBOOK_OUT ${CMAKE_CURRENT_BINARY_DIR}/notebook_out)
file(MAKE_DIRECTORY ${CLOTHLAB_NOTEBOOK_INPUTS}/bench ${CLOTHLAB_NOTEBOOK_OUT})

# Inputs. The trace follows three vertices (the bottom middle, a bottom corner and a pinned top
# corner) so the figures show several lines.
clothlab_cli_test(notebook.inputs.trace 0 "trace: 0\\.49972 s simulated .*wrote .*trace\\.csv"
  trace ${CLOTHLAB_DEFAULT_SCENE} --duration 0.5 --out ${CLOTHLAB_NOTEBOOK_INPUTS}/trace.csv
  --set "trace.vertices=[[16,31],[0,31],[31,0]]")
clothlab_cli_test(notebook.inputs.accuracy 0 "wrote .*accuracy\\.csv"
  bench --suite accuracy --quick --out ${CLOTHLAB_NOTEBOOK_INPUTS}/bench/accuracy.csv)
clothlab_cli_test(notebook.inputs.stability 0
  "wrote .*stability\\.csv.*wrote .*stability_stress\\.csv"
  bench --suite stability --quick --out ${CLOTHLAB_NOTEBOOK_INPUTS}/bench/stability.csv)
clothlab_cli_test(notebook.inputs.largestep 0
  "wrote .*largestep\\.csv.*wrote .*largestep_ladder\\.csv.*wrote .*largestep_summary\\.csv"
  bench --suite largestep --quick --out ${CLOTHLAB_NOTEBOOK_INPUTS}/bench/largestep.csv)
set_tests_properties(cli.notebook.inputs.trace PROPERTIES FIXTURES_SETUP notebook_input_traces)
set_tests_properties(cli.notebook.inputs.accuracy PROPERTIES
  FIXTURES_SETUP notebook_input_accuracy TIMEOUT 180)
set_tests_properties(cli.notebook.inputs.stability PROPERTIES
  FIXTURES_SETUP notebook_input_stability TIMEOUT 120)
set_tests_properties(cli.notebook.inputs.largestep PROPERTIES
  FIXTURES_SETUP notebook_input_largestep TIMEOUT 120)

# notebook.NAME runs the notebook; notebook.NAME.FIGURE checks each PNG it must write (a blank
# matplotlib figure of this size is about 25 kB; the smallest real one about 40 kB).
set(CLOTHLAB_NOTEBOOK_FIGURES_traces position velocity force energy)
set(CLOTHLAB_NOTEBOOK_FIGURES_accuracy work_precision error_vs_dt)
set(CLOTHLAB_NOTEBOOK_FIGURES_stability map bars ratio stress)
set(CLOTHLAB_NOTEBOOK_FIGURES_largestep work_precision winners)
# Figures of a few flat bars compress below the size check's threshold when the measured costs
# shift (28.8 kB seen, an empty frame with its labels is 28.1 kB): they are checked for coloured
# marks instead (tests/check_colour.py).
set(CLOTHLAB_NOTEBOOK_FLAT_FIGURES largestep_winners)
set(CLOTHLAB_NOTEBOOK_ENVIRONMENT
  "CLOTHLAB_TRACE_CSV=${CLOTHLAB_NOTEBOOK_INPUTS}/trace.csv"
  "CLOTHLAB_BENCH_DIR=${CLOTHLAB_NOTEBOOK_INPUTS}/bench"
  "CLOTHLAB_FIGURES=${CLOTHLAB_NOTEBOOK_OUT}")
foreach(name traces accuracy stability largestep)
  add_test(NAME notebook.${name}
    COMMAND ${PROJECT_SOURCE_DIR}/scripts/notebooks --no-deps ${name})
  set_tests_properties(notebook.${name} PROPERTIES
    ENVIRONMENT "${CLOTHLAB_NOTEBOOK_ENVIRONMENT}"
    FIXTURES_REQUIRED notebook_input_${name}
    FIXTURES_SETUP notebook_figures_${name}
    TIMEOUT 120)
  foreach(figure ${CLOTHLAB_NOTEBOOK_FIGURES_${name}})
    set(png ${CLOTHLAB_NOTEBOOK_OUT}/${name}_${figure}.png)
    if("${name}_${figure}" IN_LIST CLOTHLAB_NOTEBOOK_FLAT_FIGURES)
      add_test(NAME notebook.${name}.${figure}
        COMMAND /usr/bin/python3 ${CMAKE_CURRENT_LIST_DIR}/check_colour.py ${png} 0.02)
    else()
      add_test(NAME notebook.${name}.${figure}
        COMMAND ${CMAKE_COMMAND} -DFILE=${png} -DMIN_BYTES=30000
          -P ${CMAKE_CURRENT_LIST_DIR}/check_png.cmake)
    endif()
    set_tests_properties(notebook.${name}.${figure} PROPERTIES
      FIXTURES_REQUIRED notebook_figures_${name})
  endforeach()
endforeach()

# sweep.ipynb runs its own sweep through the Python module (the 3 x 3 grid per integrator of
# CLOTHLAB_SWEEP_QUICK, on a LocalCluster of two workers: alone). Its map is a few squares and
# crosses: checked for coloured marks.
if(CLOTHLAB_PYTHON)
  add_test(NAME notebook.sweep COMMAND ${PROJECT_SOURCE_DIR}/scripts/notebooks --no-deps sweep)
  set_tests_properties(notebook.sweep PROPERTIES
    ENVIRONMENT "CLOTHLAB_FIGURES=${CLOTHLAB_NOTEBOOK_OUT};CLOTHLAB_SWEEP_QUICK=1"
    FIXTURES_SETUP notebook_figures_sweep RUN_SERIAL TRUE TIMEOUT 300)
  add_test(NAME notebook.sweep.map
    COMMAND /usr/bin/python3 ${CMAKE_CURRENT_LIST_DIR}/check_colour.py
      ${CLOTHLAB_NOTEBOOK_OUT}/sweep_map.png 0.02)
  set_tests_properties(notebook.sweep.map PROPERTIES FIXTURES_REQUIRED notebook_figures_sweep)
endif()

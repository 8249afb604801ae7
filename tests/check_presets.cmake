# The debug test preset's exclusion list (CMakePresets.json) in CMake's own regular-expression
# engine, the one ctest uses: it allows at most nine groups, and ctest runs every test, excluding
# none, when the expression does not compile. Names it must exclude, and one it must keep; with
# CTEST and BUILD_DIR, also that no test the exclusions keep needs a fixture only an excluded test
# sets up (ctest would run it without the file that test writes).
cmake_policy(VERSION 3.25)
file(READ ${PRESETS} json)
string(JSON count LENGTH "${json}" testPresets)
math(EXPR last "${count} - 1")
foreach(i RANGE ${last})
  string(JSON name GET "${json}" testPresets ${i} name)
  if(name STREQUAL "debug")
    string(JSON regex GET "${json}" testPresets ${i} filter exclude name)
  endif()
endforeach()
foreach(test Multigrid.IterationsStayNearlyFlatAsTheGridGrows ShippedView.ForceArrowsShowAtRest
             Dance.SameResultForAnyThreadCount ClothContact.FastDropLandsOnTheThinTable
             ShippedScenes.DropBoxSheetSlidesOffOntoTheFloor cli.bench.stability_quick
             cli.trace.diverges_10x.explicit_euler
             ImplicitEuler.MatchesRk4OnTheFallingSheetAtSmallSteps
             SmallSteps.ErrorAtOneSecondFallsAsSubstepsDouble
             SmallSteps.ErrorInABreezeNeverGrowsWithSubsteps
             LargeStep/LargeStepOrder.SingleSpringIsFirstOrder/vbd)
  string(REGEX MATCH "${regex}" hit "${test}")
  if(NOT hit)
    message(FATAL_ERROR "the debug preset's exclusions do not exclude ${test}")
  endif()
endforeach()
string(REGEX MATCH "${regex}" hit "Dance.SolesStayOnTheFloor")
if(hit)
  message(FATAL_ERROR "the debug preset's exclusions exclude Dance.SolesStayOnTheFloor")
endif()
if(CTEST AND BUILD_DIR)
  execute_process(COMMAND ${CTEST} --show-only=json-v1 -E "${regex}" WORKING_DIRECTORY ${BUILD_DIR}
                  OUTPUT_VARIABLE listing RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "ctest --show-only failed in ${BUILD_DIR}")
  endif()
  string(REGEX REPLACE "[ \t\r\n]" "" listing "${listing}")
  foreach(kind SETUP REQUIRED)
    string(REGEX MATCHALL "\"name\":\"FIXTURES_${kind}\",\"value\":\\[[^]]*\\]" found
           "${listing}")
    set(${kind})
    foreach(entry IN LISTS found)
      string(REGEX MATCHALL "\"[^\"]+\"" names "${entry}")
      foreach(name IN LISTS names)
        string(REPLACE "\"" "" name "${name}")
        if(NOT name MATCHES "^(name|FIXTURES_${kind}|value)$")
          list(APPEND ${kind} ${name})
        endif()
      endforeach()
    endforeach()
  endforeach()
  if(NOT SETUP)
    message(FATAL_ERROR "no fixture set up among the kept tests: the listing was not read")
  endif()
  foreach(fixture IN LISTS REQUIRED)
    if(NOT fixture IN_LIST SETUP)
      message(FATAL_ERROR "a kept test needs fixture ${fixture}, whose setup the exclusions drop")
    endif()
  endforeach()
endif()
message(STATUS "the debug preset's exclusions compile and exclude what they name")

# The debug test preset's exclusion list (CMakePresets.json) in CMake's own regular-expression
# engine, the one ctest uses: it allows at most nine groups, and ctest runs every test, excluding
# none, when the expression does not compile. Names it must exclude, and one it must keep.
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
             ImplicitEuler.MatchesRk4OnTheFallingSheetAtSmallSteps)
  string(REGEX MATCH "${regex}" hit "${test}")
  if(NOT hit)
    message(FATAL_ERROR "the debug preset's exclusions do not exclude ${test}")
  endif()
endforeach()
string(REGEX MATCH "${regex}" hit "Dance.SolesStayOnTheFloor")
if(hit)
  message(FATAL_ERROR "the debug preset's exclusions exclude Dance.SolesStayOnTheFloor")
endif()
message(STATUS "the debug preset's exclusions compile and exclude what they name")

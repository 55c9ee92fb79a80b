# bad_scenarios.cmake: one CTest test per bad scenario, included from tests/CMakeLists.txt.
#
#   bad/<stem>      tests/bad/<stem>.ini must be rejected as its "; expect:" line says
#   bad/valid       tests/bad/valid.ini.txt must be accepted (the driver's control case)
#   bad/valid_coin_pi  a coin ([disk] thickness) with angles as multiples of pi, accepted
#   bad/directory   a directory given as the scenario
#   bad/unreadable  a chmod 000 scenario (skipped, exit 77, when running as root)
#   bad/missing     a scenario file that does not exist: "FILE: cannot open: ..." (no line)
#   bad/empty       an empty scenario file
#   bad/binary      a scenario file of non-UTF-8 bytes
# Each runs tests/check_bad_scenario.sh with the diskval executable; see that
# script for what "rejected cleanly" means.

if(NOT TARGET diskval)
  message(WARNING "bad_scenarios.cmake: no diskval target, bad-scenario tests not added")
  return()
endif()

find_program(DV_BASH bash REQUIRED)
set(_dv_bad_dir ${CMAKE_CURRENT_LIST_DIR}/bad)
set(_dv_bad_check ${DV_BASH} ${CMAKE_CURRENT_LIST_DIR}/check_bad_scenario.sh $<TARGET_FILE:diskval>)

file(GLOB _dv_bad_files LIST_DIRECTORIES false CONFIGURE_DEPENDS ${_dv_bad_dir}/*.ini)
list(SORT _dv_bad_files)
set(_dv_bad_tests)
foreach(_f IN LISTS _dv_bad_files)
  get_filename_component(_stem ${_f} NAME_WLE)
  add_test(NAME bad/${_stem} COMMAND ${_dv_bad_check} ${_f})
  list(APPEND _dv_bad_tests bad/${_stem})
endforeach()

# a directory named like a scenario, made at configure time
set(_dv_bad_subdir ${CMAKE_CURRENT_BINARY_DIR}/bad_scenario_directory.ini)
file(MAKE_DIRECTORY ${_dv_bad_subdir})

add_test(NAME bad/valid COMMAND ${_dv_bad_check} ${_dv_bad_dir}/valid.ini.txt --valid)
add_test(NAME bad/valid_bom_repeats COMMAND ${_dv_bad_check} ${_dv_bad_dir}/valid_bom_repeats.ini.txt --valid)
add_test(NAME bad/valid_coin_pi COMMAND ${_dv_bad_check} ${_dv_bad_dir}/valid_coin_pi.ini.txt --valid)
add_test(NAME bad/directory COMMAND ${_dv_bad_check} ${_dv_bad_subdir})
add_test(NAME bad/unreadable COMMAND ${_dv_bad_check} ${_dv_bad_dir}/valid.ini.txt --unreadable)
add_test(NAME bad/missing COMMAND ${_dv_bad_check} ${CMAKE_CURRENT_BINARY_DIR}/nosuch.ini --missing)
add_test(NAME bad/empty COMMAND ${_dv_bad_check} ${_dv_bad_dir}/empty.ini.txt --empty)
add_test(NAME bad/binary COMMAND ${_dv_bad_check} ${_dv_bad_dir}/binary.ini.bin --binary)
list(APPEND _dv_bad_tests bad/valid bad/valid_bom_repeats bad/valid_coin_pi bad/directory bad/unreadable bad/missing bad/empty bad/binary)

# the driver itself limits each run to 20 s (plus 5 s to kill)
set_tests_properties(${_dv_bad_tests} PROPERTIES LABELS bad TIMEOUT 40)
set_tests_properties(bad/unreadable PROPERTIES SKIP_RETURN_CODE 77)

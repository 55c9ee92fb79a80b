# The test tiers: every test of the calling directory gets the label "quick"
# unless it is named in DV_SLOW_TESTS, which get "slow". `ctest -L quick` is the
# tier a change is checked with first (docs/tests.md); `./run.sh test` runs both.
set(DV_SLOW_TESTS
    # end-to-end runs of whole scenes, repeated or under a tool (minutes)
    valgrind scenario_with memory_budget determinism suite_cli suite_render scene long_run
    cli/analyze_range cli/verify_converges cli/progress_line
    # end-to-end repeats of code the quick tier runs in shorter tests (as the sanitizer
    # build's list says, tests/CMakeLists.txt): the hoop's horizon and quick cause
    # (shadow_fall, cli/cause_quick), suite --verify (verify_judge, json_schemas),
    # the settings choice's report and cause (cli/settings_choice_deterministic, verdicts)
    cli/hoop cli/suite_verify cli/settings_choice_reported cli/settings_choice_cause
    # the objects of issue 48 (a hoop for 10 s, a washer) in every engine: 60 s
    shadow_objects
    # what the machine has: Node, MPI, an install, a fuzzer built on its own
    adapters_node mpi package fuzz_scenario
    # time limits: waits that must outlast a limit (20-50 s)
    timeout)

function(dv_label_test_tiers)
  get_property(tests DIRECTORY PROPERTY TESTS)
  set(slow_fixtures "")
  foreach(t IN LISTS tests)
    if(t IN_LIST DV_SLOW_TESTS)
      set_property(TEST ${t} APPEND PROPERTY LABELS slow)
      get_property(setup TEST ${t} PROPERTY FIXTURES_SETUP)
      list(APPEND slow_fixtures ${setup})
    else()
      set_property(TEST ${t} APPEND PROPERTY LABELS quick)
    endif()
  endforeach()
  # `ctest -L quick` runs the setup of every fixture a quick test requires: a slow one
  # (suite_cli sets up suite_render's) would bring its minutes into the quick tier
  foreach(t IN LISTS tests)
    if(NOT t IN_LIST DV_SLOW_TESTS)
      get_property(required TEST ${t} PROPERTY FIXTURES_REQUIRED)
      foreach(f IN LISTS required)
        if(f IN_LIST slow_fixtures)
          message(FATAL_ERROR "quick test ${t} requires fixture ${f}, set up by a slow test")
        endif()
      endforeach()
    endif()
  endforeach()
endfunction()

# The test tiers: every test of the calling directory gets the label "quick"
# unless it is named in DV_SLOW_TESTS, which get "slow". `ctest -L quick` is the
# tier a change is checked with first (docs/tests.md); `./run.sh test` runs both.
set(DV_SLOW_TESTS
    # end-to-end runs of whole scenes, repeated or under a tool (minutes)
    valgrind scenario_with memory_budget read_once determinism suite_cli suite_render scene long_run
    cli/analyze_range cli/verify_converges cli/progress_line
    # what the machine has: Node, MPI, an install, a fuzzer built on its own
    adapters_node mpi package fuzz_scenario
    # time limits and forecasts
    timeout best_forecast)

function(dv_label_test_tiers)
  get_property(tests DIRECTORY PROPERTY TESTS)
  foreach(t IN LISTS tests)
    if(t IN_LIST DV_SLOW_TESTS)
      set_property(TEST ${t} APPEND PROPERTY LABELS slow)
    else()
      set_property(TEST ${t} APPEND PROPERTY LABELS quick)
    endif()
  endforeach()
endfunction()

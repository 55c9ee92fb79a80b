# check_lib.sh: sourced by the fault scripts (check_faults.sh,
# check_output_faults.sh, check_suite_faults.sh).
# check COND WHAT: evaluate COND; when it is false print "FAIL: WHAT" and set
# fail=1, which the script exits with.
fail=0
check() { if ! eval "$1"; then echo "FAIL: $2"; fail=1; fi; }

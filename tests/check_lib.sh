# check_lib.sh: sourced by the fault scripts (check_faults.sh,
# check_output_faults.sh, check_suite_faults.sh).
# check COND WHAT: evaluate COND; when it is false print "FAIL: WHAT" and set
# fail=1, which the script exits with.
fail=0
check() { if ! eval "$1"; then echo "FAIL: $2"; fail=1; fi; }

# refused WHAT REGEX CMD...: exit 2, one stderr line matching REGEX (its output
# goes to $work/stdout and $work/stderr: the caller sets work)
refused() {
  local what=$1 regex=$2
  shift 2
  "$@" >"$work/stdout" 2>"$work/stderr"
  local code=$?
  check '[ $code -eq 2 ] && [ "$(wc -l <"$work/stderr")" -eq 1 ] && grep -Eq -e "$regex" "$work/stderr"' \
    "$what: exit $code, want 2 and one line matching '$regex': $(cat "$work/stderr")"
}

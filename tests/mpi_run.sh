# mpi_run.sh, sourced: mpi_run NP COMMAND [ARGS...] runs COMMAND on NP ranks of
# this machine (oversubscribed; as root where the tests run as root).
mpi_run() {
  local np=$1 root=()
  shift
  [ "$(id -u)" -eq 0 ] && root=(--allow-run-as-root)
  mpirun "${root[@]}" --oversubscribe -np "$np" "$@"
}

# a scratch directory removed at exit, in $work
mpi_scratch() {
  work=$(mktemp -d)
  trap 'rm -rf "$work"' EXIT
}

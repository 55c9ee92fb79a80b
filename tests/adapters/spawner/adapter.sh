#!/bin/sh
# A test adapter (tests/check_adapter_children.sh): the replay adapter
# (../replay/adapter.sh, every mode of it) that first starts two children of
# its own, which must end with its run: `sleep 1001.$DV_SPAWN_TAG` in a session
# of its own (setsid: out of the adapter's process group) and
# `sleep 1000.$DV_SPAWN_TAG` in the background. It appends to $DV_SPAWN_LOG
# "parent PID" (the process that started it) and "child PID" for each child.
# Neither child holds the adapter's pipes (the run is the replay's).
# DV_SPAWN_MODE, once they run: killguard kills the process that started it
# (diskval's guard: `kill -9 $PPID`, and the adapter dies with it), stopguard
# stops it (`kill -STOP $PPID`) and replays on; anything else, nothing.
if [ "$1" = --version ]; then echo "spawner 1 (a test adapter)"; exit 0; fi
if [ -n "${DV_SPAWN_TAG:-}" ]; then
  echo "parent $PPID" >>"$DV_SPAWN_LOG"
  setsid sleep "1001.$DV_SPAWN_TAG" </dev/null >/dev/null 2>&1 &
  echo "child $!" >>"$DV_SPAWN_LOG"
  sleep "1000.$DV_SPAWN_TAG" </dev/null >/dev/null 2>&1 &
  echo "child $!" >>"$DV_SPAWN_LOG"
  case "${DV_SPAWN_MODE:-}" in
  killguard) kill -9 "$PPID"; sleep 5; exit 3 ;; # killed before the sleep ends
  stopguard) kill -STOP "$PPID" ;;
  esac
fi
exec sh ../replay/adapter.sh

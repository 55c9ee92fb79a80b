#!/bin/sh
# A test adapter (tests/check_adapter_children.sh): the replay adapter
# (../replay/adapter.sh, every mode of it) that first starts two children of
# its own, which must end with its run: `sleep 1001.$DV_SPAWN_TAG` in a session
# of its own (setsid: out of the adapter's process group) and
# `sleep 1000.$DV_SPAWN_TAG` in the background. It appends to $DV_SPAWN_LOG
# "parent PID" (the process that started it) and "child PID" for each child.
# Neither child holds the adapter's pipes (the run is the replay's).
if [ "$1" = --version ]; then echo "spawner 1 (a test adapter)"; exit 0; fi
if [ -n "${DV_SPAWN_TAG:-}" ]; then
  echo "parent $PPID" >>"$DV_SPAWN_LOG"
  setsid sleep "1001.$DV_SPAWN_TAG" </dev/null >/dev/null 2>&1 &
  echo "child $!" >>"$DV_SPAWN_LOG"
  sleep "1000.$DV_SPAWN_TAG" </dev/null >/dev/null 2>&1 &
  echo "child $!" >>"$DV_SPAWN_LOG"
fi
exec sh ../replay/adapter.sh

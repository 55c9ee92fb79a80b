#!/usr/bin/env bash
# check_layers.sh SOURCE_DIR: the layers depend one way (README, "Architecture").
#
# Every #include "x.h" in a layer's .c and .h files must name a header of
# that layer or of one below it; no file outside engines/ (and the tests and
# benchmarks) names a concrete engine, by its type or by its name in quotes.
# Prints each violation as FILE:LINE: what; exit 1 if there is any.
set -u
src=${1:?usage: check_layers.sh SOURCE_DIR}
cd "$src" || exit 2

# a layer and what it may include, lowest first
declare -A allowed=(
  [common]="common"
  [reduced]="reduced common"
  [scenario]="scenario reduced common"
  [engines]="engines scenario reduced common"
  [io]="io common"
  [exec]="exec common"
  [run]="run io exec engines scenario reduced common"
  [report]="report run io exec engines scenario reduced common"
  [search]="search report run io exec engines scenario reduced common"
  [cli]="cli search report run io exec engines scenario reduced common"
)

# the layer that holds header h
layer_of() {
  for l in "${!allowed[@]}"; do
    [ -f "$l/$1" ] && { echo "$l"; return; }
  done
}

bad=0
for layer in "${!allowed[@]}"; do
  for f in "$layer"/*.c "$layer"/*.h; do
    [ -f "$f" ] || continue
    while IFS=: read -r line header; do
      owner=$(layer_of "$header")
      [ -n "$owner" ] || continue # a library's header
      case " ${allowed[$layer]} " in
        *" $owner "*) ;;
        *) echo "$f:$line: includes $owner/$header: $layer may not depend on $owner"; bad=1 ;;
      esac
    done < <(grep -n '^#include "' "$f" | sed 's/^\([0-9]*\):#include "\([^"]*\)".*/\1:\2/')
  done
done

# engines in C, and those in C++ in a folder of their own (engines/NAME/*.cc)
engines=$(sed -n 's/^\(extern "C" \)\{0,1\}const dv_engine_type \(dv_engine_[a-z_]*\) = .*/\2/p' \
  engines/*.c engines/*/*.cc)
names=$( (grep -ho '^    .name = "[a-z_]*"' engines/engine_*.c | sed 's/.*"\(.*\)"/\1/'
  sed -n '/^extern "C" const dv_engine_type/{n;s/^ *"\([a-z_]*\)",.*/\1/p}' engines/*/*.cc))
for layer in "${!allowed[@]}"; do
  [ "$layer" = engines ] && continue
  for f in "$layer"/*.[ch]; do
    [ -f "$f" ] || continue
    code=$(sed 's|/\*.*\*/||; s|^ *\*.*||; s|^ */\*.*||' "$f") # comments may name engines
    for e in $engines; do
      grep -n "\b$e\b" <<<"$code" | sed "s|^|$f:|; s|\$|  (names the engine $e)|" | grep . && bad=1
    done
    for n in $names; do
      grep -n "\"$n[\",]\|[ ,]$n\"" <<<"$code" | sed "s|^|$f:|; s|\$|  (names the engine '$n')|" |
        grep . && bad=1
    done
  done
done
# C++ only inside an engine's own folder (engines/NAME/) and common/dv_format.cc: no
# other C or header file includes a C++ header
for f in $(find common reduced scenario engines io exec run report search cli api include \
  -maxdepth 1 -name '*.[ch]'); do
  grep -n '^#include <\(bt[A-Za-z]*\|Bullet[A-Za-z/]*\|LinearMath/[A-Za-z]*\)\.h>\|^#include <c[a-z]*>$\|^#include <[a-z_]*>$' "$f" |
    grep -v '\.h>' | sed "s|^|$f:|; s|\$|  (a C++ header outside an engine's folder)|" | grep . && bad=1
  grep -n '^#include <\(bt[A-Za-z]*\|Bullet[A-Za-z/]*\|LinearMath/[A-Za-z]*\)\.h>' "$f" |
    sed "s|^|$f:|; s|\$|  (Bullet outside engines/bullet/)|" | grep . && bad=1
  grep -n '^#include <dart/' "$f" |
    sed "s|^|$f:|; s|\$|  (DART outside engines/dart/)|" | grep . && bad=1
done
[ $bad -eq 0 ] && echo "layers: every include goes downwards; no engine named outside engines/"
exit $bad

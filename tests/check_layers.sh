#!/usr/bin/env bash
# check_layers.sh SOURCE_DIR: the layers depend one way (docs/architecture.md).
#
# Every #include "x.h" in a layer's .c and .h files must name a header of
# that layer or of one below it, and an engine's own header (engines/NAME/)
# serves its folder only; no file outside engines/NAME/ (but the registry
# engines/dv_engines.def, the tests and the benchmarks) names the engine NAME,
# by its table or by its name in quotes; C++ stays in the engines' folders;
# no folder holds more than 15 C or C++ files.
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

# the layer that holds each file name (in the layer's folder or one below it; the first
# layer found, as the loops below meet them), and the engine folder of an engine's own files
declare -A owner_of home_of
for l in "${!allowed[@]}"; do
  for p in "$l"/* "$l"/*/*; do
    [ -f "$p" ] && [ -z "${owner_of[${p##*/}]:-}" ] && owner_of[${p##*/}]=$l
  done
done
for p in engines/*/*; do
  [ -f "$p" ] && [ -z "${home_of[${p##*/}]:-}" ] && home_of[${p##*/}]=$p
done

# a layer's own files, its subfolders' included
layer_files() { find "$1" \( -name '*.c' -o -name '*.h' -o -name '*.cc' \) | sort; }

bad=0
for layer in "${!allowed[@]}"; do
  for f in $(layer_files "$layer"); do
    while IFS=: read -r line header; do
      owner=${owner_of[$header]:-}
      [ -n "$owner" ] || continue # a library's header
      case " ${allowed[$layer]} " in
        *" $owner "*) ;;
        *) echo "$f:$line: includes $owner/$header: $layer may not depend on $owner"; bad=1 ;;
      esac
      # an engine's own headers serve its folder only
      home=${home_of[$header]:-}
      if [ -n "$home" ] && [ "${home%/*}" != "${f%/*}" ]; then
        echo "$f:$line: includes $home: an engine's header outside its folder"; bad=1
      fi
    done < <(grep -n '^#include "' "$f" | sed 's/^\([0-9]*\):#include "\([^"]*\)".*/\1:\2/')
  done
done

# the registry names every engine: DV_ENGINE(NAME), its table dv_engine_NAME in engines/NAME/
engines=$(sed -n 's/^DV_ENGINE(\([a-z_0-9]*\)).*/\1/p' engines/dv_engines.def)
[ -n "$engines" ] || { echo "engines/dv_engines.def: no engine"; bad=1; }
for e in $engines; do
  grep -qs "const dv_engine_type dv_engine_$e = " engines/"$e"/*.c engines/"$e"/*.cc ||
    { echo "engines/$e/: no table dv_engine_$e (dv_engines.def names it)"; bad=1; }
done
# no file outside engines/NAME/ (but the registry, tests and benchmarks) names engine NAME,
# by its table or by its name in quotes; comments may name engines. One grep a file for
# every engine at once; each hit then says which engine it named.
alt=$(echo $engines | tr ' ' '|')
for layer in "${!allowed[@]}"; do
  for f in $(layer_files "$layer"); do
    case "$(basename "$f")" in test_*) continue ;; esac
    while IFS=: read -r line hit; do
      [[ $hit =~ ($alt) ]] && e=${BASH_REMATCH[1]} # the engine named
      case "$f" in engines/"$e"/*) continue ;; esac
      case "$hit" in
        dv_engine_*) echo "$f:$line: $hit  (names the engine dv_engine_$e)"; bad=1 ;;
        *)
          # a quoted name: anywhere but in an engine's folder, where "ode" may be a
          # value of its own (DART's collision detector), not the engine
          case "$f" in engines/*/*) continue ;; esac
          echo "$f:$line: $hit  (names the engine '$e')"; bad=1 ;;
      esac
    done < <(sed 's|/\*.*\*/||; s|//.*||; s|^ *\*.*||; s|^ */\*.*||' "$f" |
      grep -noE "\bdv_engine_($alt)\b|\"($alt)[\",]|[ ,]($alt)\"")
  done
done
# C++ only inside an engine's own folder (engines/NAME/) and common/dv_format.cc: no other
# file is C++ or includes a C++ header (a standard one, or an engine library's)
cxx='^#include <\(c[a-z]*\|[a-z_]*\|[^>]*\.hpp\|bt[A-Za-z]*\.h\|Bullet[A-Za-z/]*\.h\|LinearMath/[A-Za-z]*\.h\|Simbody\.h\|SimTK[^>]*\|simbody/[^>]*\|simmath/[^>]*\|dart/[^>]*\)>'
for f in $(find common reduced scenario engines io exec run report search cli api include \
  \( -name '*.[ch]' -o -name '*.cc' \) ! -path 'engines/*/*' | sort); do
  [ "$f" = common/dv_format.cc ] && continue
  case "$f" in *.cc) echo "$f: C++ outside an engine's folder"; bad=1; continue ;; esac
  grep -n "$cxx" "$f" | sed "s|^|$f:|; s|\$|  (a C++ header outside an engine's folder)|" | grep . && bad=1
done
# small folders: none holds more than 15 C or C++ files (group them as their parts suggest)
for d in $(find . -path ./build\* -prune -o -path ./.git -prune -o -type d -print); do
  n=$(find "$d" -maxdepth 1 \( -name '*.c' -o -name '*.cc' \) | wc -l)
  [ "$n" -gt 15 ] && { echo "$d: $n C/C++ files, more than 15"; bad=1; }
done
[ $bad -eq 0 ] && echo "layers: every include goes downwards; every engine in its own folder, named nowhere else"
exit $bad

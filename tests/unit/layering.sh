#!/bin/bash
#------------------------------------------------------------------------------
# savageHutterFoam: Savage-Hutter granular avalanche solver
#
# Description
#     The folders of the solver core include one another in one direction
#     only, each only those before it in
#         physics  parallel  host  ensemble  cpu | cuda
#     (physics: the pointwise physics; parallel: the seam of decomposed
#     runs; host: problems and the solver interface, decomposition;
#     ensemble: batches of variants; cpu, cuda: the backends, which do not
#     include each other).  Prints every include between folders and
#     fails on one against that order.
#
# Usage
#     layering.sh <project dir>
#------------------------------------------------------------------------------
set -u
cd "$1/src/savageHutter" || exit 1
order="physics parallel host ensemble cpu cuda"
rank()
{
    case "$1" in
        physics) echo 0 ;; parallel) echo 1 ;; host) echo 2 ;;
        ensemble) echo 3 ;; cpu|cuda) echo 4 ;; *) echo -1 ;;
    esac
}
bad=0
seen=0
for f in */*.H */*.C */*.cu */*/*.H
do
    [ -f "$f" ] || continue
    from="${f%%/*}"
    while IFS= read -r inc
    do
        # The file included: beside the includer, or from the core's root
        # (the include directory of the library)
        target="$(realpath -m --relative-to=. "$(dirname "$f")/$inc")"
        [ -f "$target" ] || target="$(realpath -m --relative-to=. "$inc")"
        [ -f "$target" ] || continue
        to="${target%%/*}"
        [ "$to" != "$from" ] || continue
        seen=$((seen + 1))
        rf=$(rank "$from")
        rt=$(rank "$to")
        if [ "$rt" -lt 0 ] || [ "$rf" -lt 0 ] || [ "$rt" -ge "$rf" ]
        then
            echo "FAIL  $f includes $inc: $to is not before $from in ($order)"
            bad=$((bad + 1))
        fi
    done < <(sed -n 's/^[[:space:]]*#[[:space:]]*include[[:space:]]*"\([^"]*\)".*/\1/p' "$f")
done
echo "$seen includes between folders of src/savageHutter, $bad against the order ($order)"
[ "$seen" -gt 0 ] && [ "$bad" -eq 0 ]

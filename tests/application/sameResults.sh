#!/bin/bash
#------------------------------------------------------------------------------
# savageHutterFoam: Savage-Hutter granular avalanche solver
#
# Description
#     Nothing changes in results: runs every tutorial shortened (SH_SHORT=1,
#     a tutorial with a file notTested skipped as in tutorialTests.sh;
#     its Allrun as a user runs it), in double and in single precision, and
#     lists every file the runs write with its SHA-256 (the logs aside: they
#     hold wall times and paths).  With -record the list is written to the
#     manifest; without, it is compared with the manifest, file by file,
#     byte for byte: a tutorial and precision passes when the same files
#     are written with the same bytes.
#
#     Used around a change that must not change results (a restructuring):
#         sameResults.sh <project> /tmp/before before.sha -record   # old tree
#         sameResults.sh <project> /tmp/after  before.sha           # new tree
#     and on the GPU machine (tests/gpuCheck) with -backend cuda against a
#     manifest recorded on the CPU: CUDA double equals CPU double bit for
#     bit, and CUDA single CPU single unless the CUDA backend was built with
#     approximate division and square root (then single is reported, not
#     checked).
#
#     The precision and backend reach savageHutterFoam through a wrapper
#     first on PATH (the Allrun scripts call it by name): it adds
#     -precision and -backend to every call.
#
#     -solverOnly: for a machine with the solver but without the tools
#     around it (the GPU machine's bundle of bin/bundleOpenFOAM: no
#     postProcess, avalancheSurface, hazardMaps or Python's numpy): these
#     and each tutorial's plot are replaced by stubs that do nothing, so
#     only what the solver and setAvalancheFields write is compared; such
#     a run compares with a manifest recorded with -solverOnly too.
#     Prints one line per tutorial and precision and "N passed, M failed,
#     K skipped".
#
# Usage
#     sameResults.sh <project dir> <work dir> <manifest> [-record]
#                    [-backend cpu|cuda] [-precision double|single]
#                    [-solverOnly] [tutorial ...]
#------------------------------------------------------------------------------
project="$(cd "$1" && pwd)" || exit 2  # absolute: listing() compares from the run's folder
work="$2"
manifest="$3"
shift 3
. "$project/tests/application/testFunctions.sh"
. "$project/etc/bashrc"
export OMP_NUM_THREADS=${OMP_NUM_THREADS:-2}
unset SH_FOAM_ARGS

record=false
solverOnly=false
backend=cpu
precisions="double single"
tutorials=()
while [ $# -gt 0 ]
do
    case "$1" in
        -record) record=true ;;
        -solverOnly) solverOnly=true ;;
        -backend) backend="$2"; shift ;;
        -precision) precisions="$2"; shift ;;
        -*) echo "sameResults.sh: unknown option $1" >&2; exit 2 ;;
        *) tutorials+=("$1") ;;
    esac
    shift
done
if [ ${#tutorials[@]} -eq 0 ]
then
    # As tutorialTests.sh: a tutorial with a file notTested waits for what
    # it needs (the file's first line says what), reported as skipped
    for d in "$project"/tutorials/*/Allrun
    do
        t="$(basename "$(dirname "$d")")"
        if [ -e "$project/tutorials/$t/notTested" ]
        then
            skip "$t (notTested: $(head -n1 "$project/tutorials/$t/notTested"))"
            continue
        fi
        tutorials+=("$t")
    done
fi
if ! $record && [ ! -f "$manifest" ]
then
    echo "sameResults.sh: no manifest $manifest (record one with -record)" >&2
    exit 2
fi

solver="$(command -v savageHutterFoam)" \
    || { echo "sameResults.sh: savageHutterFoam is not on PATH" >&2; exit 2; }

#- listing <dir> <tutorial>: "path sha256" of every file below dir that the
#  run wrote, sorted: the logs aside, and the tutorial's own files (inputs,
#  scripts) where they are unchanged copies; sorted in the C locale, so that
#  a manifest recorded on one machine compares line by line on another
#  (a UTF-8 locale's collation puts U, UMax between regime and hU)
listing()
{
    (
        cd "$1" || exit 1
        find . -type f ! -name 'log.*' ! -name '*.log' | LC_ALL=C sort \
            | while IFS= read -r f
            do
                cmp -s "$f" "$project/tutorials/$2/$f" || printf '%s\0' "$f"
            done | xargs -0 -r sha256sum | awk '{ print $2, $1 }'
    )
}

approximate=false
out="$work/manifest"
: > "$out"
for precision in $precisions
do
    wrapper="$work/wrapper.$precision"
    mkdir -p "$wrapper"
    cat > "$wrapper/savageHutterFoam" <<EOF
#!/bin/sh
exec "$solver" "\$@" -precision $precision -backend $backend
EOF
    chmod +x "$wrapper/savageHutterFoam"
    if $solverOnly
    then
        for tool in postProcess avalancheSurface hazardMaps
        do
            printf '#!/bin/sh\nexit 0\n' > "$wrapper/$tool"
            chmod +x "$wrapper/$tool"
        done
    fi
    for t in "${tutorials[@]}"
    do
        dir="$work/$precision/$t"
        mkdir -p "$work/$precision"
        cp -r "$project/tutorials/$t" "$dir"
        (cd "$dir" && ./Allclean > /dev/null 2>&1)
        if $solverOnly
        then
            printf '#!/bin/sh\nexit 0\n' > "$dir/plot"
        fi
        allrunLog="$work/$precision.$t.Allrun.log"
        if ! (cd "$dir" && PATH="$wrapper:$PATH" SH_SHORT=1 ./Allrun \
            > "$allrunLog" 2>&1)
        then
            # In single precision a plot's checks made for double (volume
            # to round-off) may fail; the files written so far are compared
            if [ "$precision" = single ] \
            && grep -q "^\./plot failed" "$allrunLog"
            then
                echo "      $t (single): its plot's checks for double failed, as they may in single; the files written are compared"
            else
                fail "$t ($precision, $backend): Allrun failed (see $allrunLog)"
                tail -n 15 "$allrunLog"
                continue
            fi
        fi
        grep -rqs "approximate" --include='log.savageHutterFoam*' "$dir" \
            && approximate=true
        listing "$dir" "$t" | sed "s|^\./|$precision/$t/|" >> "$out"
    done
done

if $record
then
    cp "$out" "$manifest"
    echo "Recorded $(wc -l < "$manifest") files in $manifest"
    pass "recorded: ${tutorials[*]} in $precisions with -backend $backend"
    finish
    exit
fi

for precision in $precisions
do
    for t in "${tutorials[@]}"
    do
        key="$precision/$t/"
        old="$(grep "^$key" "$manifest" | LC_ALL=C sort)"
        new="$(grep "^$key" "$out" | LC_ALL=C sort)"
        if [ -z "$new" ]
        then
            continue  # its Allrun failed: counted above
        fi
        if [ -z "$old" ]
        then
            fail "$t ($precision): not in the manifest $manifest"
            continue
        fi
        nFiles=$(echo "$new" | wc -l)
        differ="$(diff <(echo "$old") <(echo "$new") | grep '^[<>]' \
            | awk '{ print $2 }' | sort -u)"
        if [ -z "$differ" ]
        then
            pass "$t ($precision, $backend): all $nFiles files byte for byte the manifest's"
        elif [ "$precision" = single ] && $approximate
        then
            skip "$t (single, $backend): $(echo "$differ" | wc -l) of $nFiles files differ; the CUDA backend uses approximate division and square root, so single is not compared byte for byte"
        else
            fail "$t ($precision, $backend): $(echo "$differ" | wc -l) of $nFiles files differ, are missing or new:"
            echo "$differ" | head -n 20 | sed 's/^/      /'
        fi
    done
done
finish

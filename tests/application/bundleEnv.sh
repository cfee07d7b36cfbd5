#------------------------------------------------------------------------------
# savageHutterFoam: Savage-Hutter granular avalanche solver
#
# Description
#     Sourced by the scripts that run the application on the GPU machine,
#     which has no OpenFOAM: empties the work directory $work, unpacks
#     external/bundle.tar.xz (made by bin/bundleOpenFOAM) into it and puts
#     its executables and libraries on the paths.  Expects $project (the
#     project's root) and $work; makes both absolute and changes to
#     $project; returns non-zero when the bundle cannot be unpacked.
#------------------------------------------------------------------------------
cd "$project" || return 1
project="$(pwd)"
rm -rf "$work"
mkdir -p "$work" || return 1
work="$(cd "$work" && pwd)"
tar -xJf "$project/external/bundle.tar.xz" -C "$work" || return 1
export PATH="$work/bundle/bin:$PATH"
export LD_LIBRARY_PATH="$work/bundle/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
export WM_PROJECT_DIR="$work/bundle/OpenFOAM"
. "$project/bin/tools/RunFunctions"
#------------------------------------------------------------------------------

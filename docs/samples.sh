#!/bin/sh
# samples.sh: README.md's samples of what the programs print, printed by
# the programs themselves, so that they cannot drift. Each sample is a
# fenced block between the lines
#
#     <!-- sample: COMMAND -->
#     <!-- end sample -->
#
# and holds what COMMAND prints (standard output, then standard error),
# run by sh in a scratch folder that holds the repository's scenes/ and
# tests/ref/ and its programs as ./raytrace, ./raytrace-diff and
# ./raytrace-merge.
#
# Usage: sh docs/samples.sh [--check] [FILE]   (from the repository root,
#   after make; FILE defaults to README.md)
# Without --check it writes FILE's samples anew (make samples). With it,
# it writes nothing and fails, showing each sample that is not what its
# command prints today: times, speeds, sizes in bytes and threads aside,
# which change from run to run (tests/cli.sh runs it).

check=
[ "$1" = --check ] && { check=1; shift; }
file=${1:-README.md}
top=$(pwd)
for p in raytrace raytrace-diff raytrace-merge; do
    [ -x "$top/$p" ] || { echo "samples.sh: no ./$p: run make first" >&2; exit 2; }
done
T=$(mktemp -d "${TMPDIR:-/tmp}/raytrace-samples.XXXXXX") || exit 2
trap 'rm -rf "$T"' EXIT
mkdir -p "$T/run/tests"
ln -s "$top/scenes" "$T/run/scenes"
ln -s "$top/tests/ref" "$T/run/tests/ref"
for p in raytrace raytrace-diff raytrace-merge; do ln -s "$top/$p" "$T/run/$p"; done

# mask: the text on standard input with what changes between runs and
# builds made alike: a number before a unit of time, speed or size, and
# the threads (one in a build without OpenMP).
mask() { sed -E 's/[0-9]+(\.[0-9]+)? (s|ms|Mrays\/s|B|KB|MB|GB|KiB|MiB|GiB|threads?)\b/N \2/g'; }

# The file with each sample's block printed anew, on standard output.
n=0
: >"$T/new"
while IFS= read -r line || [ -n "$line" ]; do
    case $line in
    '<!-- sample: '*' -->')
        printf '%s\n' "$line" >>"$T/new"
        cmd=${line#'<!-- sample: '}
        cmd=${cmd%' -->'}
        (cd "$T/run" && sh -c "$cmd") >"$T/out" 2>"$T/err"
        { echo '```'; cat "$T/out" "$T/err"; echo '```'; } >>"$T/new"
        skip=1
        n=$((n + 1))
        ;;
    '<!-- end sample -->')
        printf '%s\n' "$line" >>"$T/new"
        skip=
        ;;
    *)
        [ -n "$skip" ] || printf '%s\n' "$line" >>"$T/new"
        ;;
    esac
done <"$file"
[ -z "$skip" ] || { echo "samples.sh: $file: a sample without its end line" >&2; exit 1; }
if [ -z "$check" ]; then
    cat "$T/new" >"$file"
    echo "samples.sh: $n samples written in $file"
    exit 0
fi
mask <"$file" >"$T/old-masked"
mask <"$T/new" >"$T/new-masked"
if cmp -s "$T/old-masked" "$T/new-masked"; then
    echo "samples.sh: the $n samples of $file are what the programs print"
    exit 0
fi
echo "samples.sh: $file's samples are not what the programs print now (make samples writes them):" >&2
diff "$T/old-masked" "$T/new-masked" | head -n 30 >&2
exit 1

#!/usr/bin/env bash
# Lint: no function in src/ longer than 80 lines (clang-tidy readability-function-size, LineThreshold
# 80, counted including blank lines and comments). Checks every src/**/*.cpp, and the project headers
# they include, with the compile flags of BUILD_DIR/compile_commands.json (CMake writes it at
# configure time). Prints each offending function with its length; exit 1 if there is any (or if a
# file cannot be analysed), 0 otherwise. Runs two clang-tidy processes at a time.
# Cache: scripts/function_size.cache lists content keys (scripts/function_size_keys.py: the file, every
# project header it includes, the clang-tidy version and this check's configuration) of files that
# passed; a file whose key is listed is not analysed again. --update-cache rewrites the cache with the
# keys of every file that passes in this run (run it before committing; docs/contributing.md);
# --no-cache analyses every file.
# Usage: scripts/check_function_size.sh BUILD_DIR [--update-cache|--no-cache] [FILE.cpp ...]
#        (default: every src/**/*.cpp)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
[ $# -ge 1 ] || { echo "usage: $0 BUILD_DIR [FILE.cpp ...]" >&2; exit 2; }
build=$(cd "$1" && pwd)
shift
cache_mode=read
case "${1:-}" in
  --update-cache) cache_mode=update; shift ;;
  --no-cache) cache_mode=off; shift ;;
esac
if ! command -v clang-tidy >/dev/null 2>&1; then
  echo "check_function_size: clang-tidy not found (Debian package clang-tidy; scripts/test.sh installs it)" >&2
  exit 1
fi
[ -f "$build/compile_commands.json" ] || { echo "check_function_size: no $build/compile_commands.json" >&2; exit 1; }

cd "$root"
if [ $# -gt 0 ]; then
  files=("$@")
else
  mapfile -t files < <(find src -name '*.cpp' | sort)
fi
[ ${#files[@]} -gt 0 ] || { echo "check_function_size: no source files" >&2; exit 1; }

logs=$(mktemp -d)
trap 'rm -rf "$logs"' EXIT
config='{CheckOptions: [{key: readability-function-size.LineThreshold, value: 80}]}'
cache="$root/scripts/function_size.cache"
/usr/bin/python3 "$root/scripts/function_size_keys.py" "$root" "$config" "${files[@]}" >"$logs/keys"
all_files=("${files[@]}")
if [ "$cache_mode" != off ] && [ -f "$cache" ]; then
  mapfile -t files < <(awk -v cache="$cache" '
    BEGIN { while ((getline line < cache) > 0) { split(line, kf, " "); ok[kf[1]] = 1 } }
    !($1 in ok) { print $2 }' "$logs/keys")
fi
echo "check_function_size: ${#all_files[@]} files, $(( ${#all_files[@]} - ${#files[@]} )) unchanged since their last pass (scripts/function_size.cache), ${#files[@]} to analyse"
# A unity build's compile database lists its batches, not the files: clang-tidy would guess a file's flags
# from a neighbour and miss target-specific definitions and generated headers. Then the files are analysed
# with the database of a configure-only, non-unity build tree beside it (BUILD_DIR/function_size_db).
if [ ${#files[@]} -gt 0 ] && ! grep -q "\"file\": \"$root/${files[0]}\"" "$build/compile_commands.json"; then
  db="$build/function_size_db"
  cmake -S "$root" -B "$db" -DAGGLO_UNITY=OFF -DCMAKE_EXPORT_COMPILE_COMMANDS=ON \
    -DPython_EXECUTABLE=/usr/bin/python3 >"$logs/configure.log" 2>&1 ||
    { tail -n 20 "$logs/configure.log" >&2; echo "check_function_size: configuring $db failed" >&2; exit 1; }
  build=$db
fi
export build logs config root
# One log and one exit status per file, so that the two parallel processes never interleave output.
[ ${#files[@]} -eq 0 ] || printf '%s\0' "${files[@]}" | xargs -0 -n 1 -P 2 bash -c '
  f=$1; log="$logs/$(printf "%s" "$f" | tr "/" "%")"
  clang-tidy -p "$build" --quiet --checks="-*,readability-function-size" --config="$config" \
    --header-filter="^$root/src/" "$f" >"$log.out" 2>"$log.err"
  echo $? >"$log.rc"' _

status=0
for rc in "$logs"/*.rc; do
  [ -e "$rc" ] || continue
  if [ "$(cat "$rc")" != 0 ] && ! grep -q 'readability-function-size' "${rc%.rc}.out"; then
    echo "check_function_size: clang-tidy failed on $(basename "${rc%.rc}" | tr '%' '/'):" >&2
    grep -h 'error:' "${rc%.rc}.out" "${rc%.rc}.err" | head -5 >&2 || true
    status=1
  fi
done
# Each finding once (a header is reported by every file that includes it):
#   file:line:col: function 'name' has N lines (limit 80)
shopt -s nullglob
outs=("$logs"/*.out)
found=$(cat /dev/null "${outs[@]}" | awk '
  /warning: function .* exceeds recommended size\/complexity thresholds \[readability-function-size\]/ {
    loc = $1; sub(/: *$/, "", loc); fn = $0; sub(/.*function /, "", fn); sub(/ exceeds.*/, "", fn); next }
  loc != "" && /note: [0-9]+ lines including whitespace and comments/ {
    n = $0; sub(/.*note: /, "", n); sub(/ lines including.*threshold /, " lines (limit ", n)
    print loc ": function " fn " has " n; loc = "" }
' | sed "s|^$root/||" | sort -u)
if [ -n "$found" ]; then
  echo "$found"
  echo "check_function_size: $(printf '%s\n' "$found" | wc -l) function(s) longer than 80 lines" >&2
  status=1
fi
if [ $status -eq 0 ]; then
  echo "check_function_size: ${#all_files[@]} files, no function longer than 80 lines"
  if [ "$cache_mode" = update ]; then
    # entries of files not analysed in this run stay; those of files gone from src/ are dropped
    { if [ -f "$cache" ]; then awk -v keys="$logs/keys" '
          BEGIN { while ((getline line < keys) > 0) { split(line, kf, " "); mine[kf[2]] = 1 } }
          !($2 in mine)' "$cache" \
        | while read -r k f; do if [ -f "$root/$f" ]; then echo "$k $f"; fi; done; fi
      cat "$logs/keys"; } | sort -k2 >"$cache.tmp-$$" && mv "$cache.tmp-$$" "$cache"
    echo "check_function_size: wrote $(wc -l <"$cache") keys to scripts/function_size.cache"
  fi
fi
exit $status

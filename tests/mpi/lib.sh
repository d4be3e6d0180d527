# Shared by tests/mpi/*.sh: $1 = agglo executable, $2 = source dir, $3 = mpirun.
# run_mpi K ARGS... runs `mpirun -n K agglo ARGS` (as root and beyond the core count where needed);
# same_outputs A B compares two output folders: the same files; every file by the output regression's
# checksums (tests/regression/checksums.py: timing fields stripped, results.nc by content), run.json by its
# status, journal.jsonl by its set of (key, result).
set -u
AGGLO=$1; SRC=$(cd "$2" && pwd); MPIRUN=$3
TMP=$(mktemp -d); trap 'rm -rf "$TMP"' EXIT
export TMPDIR="$TMP/tmpdir"  # where ranks other than 0 keep their scratch folders (checked by no_scratch_left)
mkdir -p "$TMPDIR"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
fail() { echo "FAIL: $*"; exit 1; }
cd "$SRC" || exit 1

run_mpi() {
  local k=$1; shift
  "$MPIRUN" -n "$k" --bind-to none "$AGGLO" "$@"
}

descendants() {  # every process below $1 (its children, theirs, ...), one pid per line
  local kids k
  kids=$(pgrep -P "$1") || return 0
  for k in $kids; do echo "$k"; descendants "$k"; done
}

own_rank() {  # the newest (highest pid) process below launcher $1 running program $2: never a process of another
  local p best=""  # test beside this one, never mpirun itself (whose arguments name the program too)
  for p in $(descendants "$1"); do
    [ "$(head -z -n 1 "/proc/$p/cmdline" 2>/dev/null | tr -d '\0')" = "$2" ] && [ "$p" -gt "${best:-0}" ] && best=$p
  done
  echo "$best"
}

journal_set() {  # journal.jsonl -> sorted "key result" lines, timing fields of the results stripped
  /usr/bin/python3 -c '
import json, sys
sys.path.insert(0, sys.argv[2])
from checksums import dropped, strip_json
def untimed(x):  # also the timing variables of the datasets in seed-ensemble results ({"name": ..., "values": ...})
    if isinstance(x, list):
        return [untimed(v) for v in x if not (isinstance(v, dict) and dropped(str(v.get("name", ""))))]
    if isinstance(x, dict):
        return {k: untimed(v) for k, v in x.items()}
    return x
rows = sorted(json.dumps([j["key"], untimed(strip_json(j["result"]))], sort_keys=True) for j in map(json.loads, open(sys.argv[1])))
print("\n".join(rows))' "$1" "$SRC/tests/regression"
}

same_outputs() {  # the regression's normalised checksums (tests/regression/checksums.py), run.json by status
  local a=$1 b=$2 rel
  [ "$(cd "$a" && find . -type f | sort)" = "$(cd "$b" && find . -type f | sort)" ] || { echo "file lists differ: $a $b"; return 1; }
  diff <(/usr/bin/python3 "$SRC/tests/regression/checksums.py" "$a" | grep -v "run.json$") \
       <(/usr/bin/python3 "$SRC/tests/regression/checksums.py" "$b" | grep -v "run.json$") || { echo "outputs differ"; return 1; }
  while IFS= read -r rel; do
    case "$rel" in
      */run.json) /usr/bin/python3 -c 'import json,sys; a,b=(json.load(open(p)) for p in sys.argv[1:]); sys.exit(a["status"]!=b["status"])' "$a/$rel" "$b/$rel" || { echo "status differs: $rel"; return 1; } ;;
      */journal.jsonl) [ "$(journal_set "$a/$rel")" = "$(journal_set "$b/$rel")" ] || { echo "journal differs: $rel"; return 1; } ;;
    esac
  done < <(cd "$a" && find . -type f | sort)
}

ranks_of() { /usr/bin/python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["ranks"])' "$1/run.json"; }

no_scratch_left() { [ -z "$(find "$TMPDIR" -maxdepth 1 -name 'agglo-rank*')" ] || fail "scratch folders left: $(ls "$TMPDIR")"; }

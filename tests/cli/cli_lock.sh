#!/usr/bin/env bash
# One writer per study, across processes (the CLI as users run it). Two writers add a small mesh to one study,
# 25 rounds each, at the same time. Truth: every add that exited 0 printed its artifact id, and that id is in the
# final manifest with an undamaged file; every add that failed exited 1 and named the lock's holder. Then a holder
# killed with SIGKILL leaves the study writable at once.
set -euo pipefail
cli=$1 work=$2 python=$3
rm -rf "$work"
mkdir -p "$work"
"$cli" phantom bifurcation --out "$work/ph" --size 32x32x16 --spacing 2,2,3 >/dev/null
study="$work/s.vsim"
"$cli" import "$work/ph/dicom" --study "$study" >/dev/null

writer() { # $1: name; 25 adds, each result in $work/$1.log as "<exit code> <artifact id or holder>"
    for round in $(seq 1 25); do
        if out=$("$cli" mesh sheet --study "$study" --width 4 --length 4 --cell 2 2>"$work/$1.err"); then
            echo "0 $(echo "$out" | "$python" -c 'import json,sys; print(json.load(sys.stdin)["artifact"])')"
        else
            code=$?
            echo "$code $(tr '\n' ' ' <"$work/$1.err")"
        fi
    done >"$work/$1.log"
}
writer a & first=$!
writer b & second=$!
wait $first $second

"$cli" info "$study" >"$work/info.json"
"$python" - "$work" <<'PY'
import json, sys, os
work = sys.argv[1]
info = json.load(open(os.path.join(work, "info.json")))
artifacts = {a["id"]: a for a in info["artifacts"]}
landed = refused = 0
for name in "ab":
    for line in open(os.path.join(work, name + ".log")):
        code, rest = line.rstrip("\n").split(" ", 1)
        if code == "0":
            landed += 1
            assert rest in artifacts, f"{rest} exited 0 but is not in the final manifest"
            assert not artifacts[rest].get("damaged"), f"{rest} is damaged"
        else:
            refused += 1
            assert code == "1", f"a refused add must exit 1, got {code}: {rest}"
            assert "being written by vascusim-cli mesh sheet (process" in rest, f"the refusal must name the holder: {rest}"
sheets = [a for a in artifacts.values() if a["kind"] == "tetmesh"]
assert len(sheets) == landed, f"{len(sheets)} meshes in the study, {landed} adds exited 0"
assert landed >= 25, f"only {landed} of 50 adds landed"
print(f"cli_lock: {landed} adds landed, {refused} refused naming the holder, none lost")
PY

# A holder killed with SIGKILL: the next writer proceeds (the kernel released the lock with the process).
"$cli" simulate fem --study "$study" --protocol thesis-rupture --param ramp_steps=1000000 --param pressure_start_mpa=0 --param pressure_end_mpa=0.01 >/dev/null 2>&1 &
holder=$!
for _ in $(seq 1 100); do
    grep -q "pid=$holder" "$study/study.lock" 2>/dev/null && break
    sleep 0.05
done
if "$cli" mesh sheet --study "$study" --width 4 --length 4 --cell 2 >/dev/null 2>"$work/held.err"; then
    echo "cli_lock: a writer got in while another held the study" >&2
    exit 1
fi
grep -q "process $holder" "$work/held.err" || { echo "cli_lock: the refusal must name process $holder" >&2; cat "$work/held.err" >&2; exit 1; }
kill -9 $holder
wait $holder 2>/dev/null || true
"$cli" mesh sheet --study "$study" --width 4 --length 4 --cell 2 >/dev/null
echo "cli_lock: the writer after a SIGKILLed holder proceeded"

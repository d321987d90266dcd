#!/bin/bash
# slurm_test.sh QUADSHADE SOURCE_DIR WORK: brings up a single-node Slurm (munged, slurmctld and
# slurmd on this machine, in WORK, on ports of their own) and runs tools/slurm/quadshade.sbatch
# through it: the catalogue suite in 4 shards (with one expected image spoiled, so that a failure
# travels through the merge too) and a 24-frame animation in 4 ranges. Passes when the merged
# report equals a single process's and every frame is byte for byte the single render's. Exits 77
# (ctest: skipped) with the reason when Slurm is not installed (Debian: slurmctld slurmd
# slurm-client munge) or cannot run here (not root, or its daemons do not come up on this
# machine: their logs are printed); once the node is up, every difference fails. Everything it
# starts it stops.
set -uo pipefail
quadshade=$1 source=$2 work=$3
skip() { echo "SKIPPED: $*"; exit 77; }
fail() { echo "slurm_test.sh: $*" >&2; exit 1; }
for tool in munged slurmctld slurmd sbatch sinfo squeue scontrol scancel; do
    command -v "$tool" >/dev/null || PATH=$PATH:/usr/sbin command -v "$tool" >/dev/null ||
        skip "Slurm is not installed ($tool missing; apt-get install slurmctld slurmd slurm-client munge)"
done
export PATH=$PATH:/usr/sbin
[[ $(id -u) -eq 0 ]] || skip "slurmd runs jobs as their users and needs root; run the test as root"

rm -rf "$work" && mkdir -p "$work"/{state,spool,munge} || exit 1
chmod 700 "$work/munge"
pids=()
cleanup() {
    scancel --quiet --full "${jobs[@]:-}" 2>/dev/null
    for pid in "${pids[@]}"; do kill "$pid" 2>/dev/null; done
    for pid in "${pids[@]}"; do wait "$pid" 2>/dev/null; done
}
jobs=()
trap cleanup EXIT

# munge authenticates slurmctld and slurmd to each other: a key and a socket of this test's own.
dd if=/dev/urandom of="$work/munge/munge.key" bs=1024 count=1 status=none && chmod 400 "$work/munge/munge.key"
socket=$work/munge/munge.socket
munged --foreground --force --key-file="$work/munge/munge.key" --socket="$socket" \
    --pid-file="$work/munge/munged.pid" --log-file="$work/munge/munged.log" --seed-file="$work/munge/munged.seed" \
    >"$work/munge/munged.out" 2>&1 &
pids+=($!)

node=$(hostname -s)
port=$((20000 + RANDOM % 20000))
cpus=$(nproc)
export SLURM_CONF=$work/slurm.conf
cat >"$SLURM_CONF" <<EOF
ClusterName=quadshade-test
SlurmctldHost=$node(127.0.0.1)
SlurmUser=root
SlurmctldPort=$port
SlurmdPort=$((port + 1))
AuthType=auth/munge
AuthInfo=socket=$socket
CredType=cred/munge
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/slurmctld.log
SlurmdLogFile=$work/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
SchedulerType=sched/backfill
MpiDefault=none
ReturnToService=2
NodeName=$node NodeAddr=127.0.0.1 CPUs=$cpus State=UNKNOWN
PartitionName=test Nodes=$node Default=YES MaxTime=INFINITE State=UP
EOF
for _ in $(seq 50); do [[ -S $socket ]] && break; sleep 0.1; done
[[ -S $socket ]] || skip "munged does not start on this machine: $(cat "$work/munge/munged.log" 2>/dev/null)"
slurmctld -D -i -f "$SLURM_CONF" >"$work/slurmctld.out" 2>&1 &
pids+=($!)
slurmd -D -f "$SLURM_CONF" -N "$node" >"$work/slurmd.out" 2>&1 &
pids+=($!)
start=$SECONDS
until sinfo --noheader --states=idle --format=%n 2>/dev/null | grep -qx "$node"; do
    ((SECONDS - start < 60)) || skip "Slurm's node does not come up on this machine in 60 s: $(tail -5 "$work"/slurm*.log)"
    sleep 0.5
done
echo "slurm_test.sh: Slurm up in $((SECONDS - start)) s ($(sinfo --version))"

export QUADSHADE=$quadshade
sbatch_wait() {  # sbatch_wait ARGS...: submits and waits (polling: sbatch --wait backs off to 30 s); fails if a task did
    local id start=$SECONDS
    id=$(sbatch --parsable --cpus-per-task=1 --chdir="$work" --output="$work/logs/%x-%A_%a.log" "$@") || return 1
    id=${id%%;*}
    jobs+=("$id")
    while [[ -n $(squeue --noheader --jobs="$id" 2>/dev/null) ]]; do
        ((SECONDS - start < 300)) || fail "job $id still running after 300 s"
        sleep 0.2
    done
    # Finished jobs stay in slurmctld's memory (MinJobAge, 300 s): every task COMPLETED, exit 0?
    local states
    states=$(scontrol --oneliner show job "$id" | grep -o 'JobState=[A-Z_]*' | sort | uniq -c)
    echo "slurm_test.sh: job $id: $states"
    [[ $(echo "$states" | grep -vc 'JobState=COMPLETED') -eq 0 ]]
}
mkdir -p "$work/logs"

# The suite, on a copy of tests/suites whose scenes are the repository's; one expected image spoiled.
mkdir -p "$work/repo/tests" && cp -r "$source/tests/suites" "$work/repo/tests/" && ln -s "$source/scenes" "$work/repo/scenes"
suite=$work/repo/tests/suites/catalogue.json
cp "$work/repo/tests/suites/catalogue/plane-perlin.png" "$work/repo/tests/suites/catalogue/plane-dots.png"
t0=$SECONDS
# The suite names the repository's scenes (../../scenes): outside its folder, so allowed.
sbatch_wait --array=1-4 --job-name=suite "$source/tools/slurm/quadshade.sbatch" test "$suite" "$work/shards" \
    --allow-outside-paths
echo "slurm_test.sh: 4-shard suite through Slurm in $((SECONDS - t0)) s"
ls "$work"/shards/shard-{1,2,3,4}.json >/dev/null || fail "missing report fragments: $(cat "$work"/logs/suite-*.log)"
"$quadshade" test --merge "$work"/shards/shard-*.json --junit "$work/merged.xml" >"$work/merged.txt" 2>&1
[[ $? -eq 3 ]] || fail "the merge did not fail on the spoiled case: $(cat "$work/merged.txt")"
"$quadshade" test "$suite" --allow-outside-paths --junit "$work/single.xml" >"$work/single.txt" 2>&1
[[ $? -eq 3 ]] || fail "the single run did not fail on the spoiled case: $(cat "$work/single.txt")"
summary() { grep '^quadshade test: ' "$1" | sed 's/ (.*//'; }
[[ "$(summary "$work/merged.txt")" == "$(summary "$work/single.txt")" ]] ||
    fail "merged: $(summary "$work/merged.txt"); single process: $(summary "$work/single.txt")"
testcases() {  # each testcase's name and failure message, in order
    sed -n 's/.*<testcase classname="[^"]*" name="\([^"]*\)".*/\1/p; s/.*<failure message="\([^"]*\)".*/  \1/p' "$1"
}
diff <(testcases "$work/merged.xml") <(testcases "$work/single.xml") || fail "the merged JUnit report differs from the single run's"
echo "slurm_test.sh: merged report = single process: $(summary "$work/merged.txt")"

# The animation: frames 0..23 in 4 ranges, against one process rendering them all.
t0=$SECONDS
sbatch_wait --array=1-4 --job-name=animation "$source/tools/slurm/quadshade.sbatch" render \
    "$source/scenes/assets/figure-1.1.gltf" 0:23 "$work/frames/frame_%04d.png" --size 316x100 ||
    fail "the animation's array failed: $(cat "$work"/logs/animation-*.log)"
echo "slurm_test.sh: 24 frames in 4 ranges through Slurm in $((SECONDS - t0)) s"
mkdir -p "$work/single-frames"
"$quadshade" render "$source/scenes/assets/figure-1.1.gltf" --frames 0:23 -o "$work/single-frames/frame_%04d.png" \
    --size 316x100 2>/dev/null || fail "the single render"
[[ $(ls "$work/frames" | wc -l) -eq 24 ]] || fail "$(ls "$work/frames" | wc -l) frames, not 24"
for f in "$work"/single-frames/*.png; do
    cmp -s "$f" "$work/frames/$(basename "$f")" || fail "$(basename "$f") differs from the single render's"
done
echo "slurm_test.sh: the 24 frames are byte for byte the single render's"

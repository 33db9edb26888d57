#!/bin/bash
# Stopping and changing a run while it goes on (docs/solver.md, "Controlling
# a run"), on the coarse dam break: stopAt writeNow, noWriteNow and
# nextWrite; controlDict read again when it changes (a new endTime applies,
# a startTime change is named as read at the next start, a controlDict that
# no longer reads is a warning and the run goes on); SIGTERM, SIGINT and
# SIGHUP (each sent twice at once: one request) write the state and end the
# process by the signal, and the run goes on from that state (ignored
# signals stay ignored);
# runTimeModifiable no leaves a changed controlDict unread.
source "$(dirname "$0")/testLib.sh"

base="$scratch/base"
cp -r "$SPHVCPM_DIR/tests/data/cases/damBreakSmall2D" "$base"
generateParticles -case "$base" > "$scratch/log.gen" 2>&1
check "generateParticles" [ $? -eq 0 ]

# newCase <name> <sed script>: a copy of the generated case with its
# controlDict edited.
newCase()
{
    rm -rf "$scratch/$1"
    cp -r "$base" "$scratch/$1"
    sed -i "$2" "$scratch/$1/system/controlDict"
    echo "$scratch/$1"
}

# timeDirs <case>: its time directories, sorted by value, on one line.
timeDirs()
{
    (cd "$1" && ls -d [0-9-]* 2>/dev/null | sort -g | tr '\n' ' ')
}

# waitFor <file> <pattern> <seconds>: until the pattern is in the file.
waitFor()
{
    local i
    for ((i = 0; i < $3*10; ++i)); do
        grep -qE -- "$2" "$1" 2>/dev/null && return 0
        sleep 0.1
    done
    return 1
}

# waitExit <pid> <seconds>: the process's exit status, or 124 (and the
# process killed) when it is still running after that long.
waitExit()
{
    local i
    for ((i = 0; i < $2*10; ++i)); do
        kill -0 "$1" 2>/dev/null || break
        sleep 0.1
    done
    if kill -0 "$1" 2>/dev/null; then
        kill -9 "$1"; wait "$1" 2>/dev/null; return 124
    fi
    wait "$1"
}

# --- stopAt at the start ---------------------------------------------------
c=$(newCase writeNow 's/^stopAt .*/stopAt writeNow;/')
sphVcpmFsi -case "$c" > "$c/log" 2>&1
check "writeNow: exit 0" [ $? -eq 0 ]
t=$(sed -n 's/^Stopped at time \([^ ]*\) by stopAt writeNow.*/\1/p' "$c/log")
check "writeNow: stopped after one step ($t)" grep -q "^Step = 1 " "$c/log"
check "writeNow: wrote that step's time only" [ "$(timeDirs "$c")" = "0 $t " ]

c=$(newCase noWriteNow 's/^stopAt .*/stopAt noWriteNow;/')
sphVcpmFsi -case "$c" > "$c/log" 2>&1
check "noWriteNow: exit 0" [ $? -eq 0 ]
expectIn "noWriteNow: says why it stopped" "$c/log" \
    "^Stopped at time .* by stopAt noWriteNow.*latest time written is 0 "
check "noWriteNow: wrote nothing" [ "$(timeDirs "$c")" = "0 " ]

c=$(newCase nextWrite 's/^stopAt .*/stopAt nextWrite;/; s/^writeInterval .*/writeInterval 0.01;/')
sphVcpmFsi -case "$c" > "$c/log" 2>&1
check "nextWrite: exit 0" [ $? -eq 0 ]
check "nextWrite: stopped at the first write time" [ "$(timeDirs "$c")" = "0 0.01 " ]
expectIn "nextWrite: says why it stopped" "$c/log" "^Stopped at time 0.01 by stopAt nextWrite"

# --- controlDict changed during the run ------------------------------------
c=$(newCase modified 's/^endTime .*/endTime 100;/; s/^writeInterval .*/writeInterval 10;/; s/^logInterval .*/logInterval 200;/')
sphVcpmFsi -case "$c" > "$c/log" 2>&1 &
pid=$!
check "modified: the loop runs" waitFor "$c/log" "^Time = " 60
# Both edits carry one modification time, as two edits within a second do
# on a file system that keeps whole seconds: the second is still seen.
sed -i 's/^endTime .*/endTime -1;/' "$c/system/controlDict"
stamp=$(stat -c %Y "$c/system/controlDict")
touch -d "@$stamp" "$c/system/controlDict"
check "modified: a controlDict that does not read is a warning" \
    waitFor "$c/log" "controlDict changed at time .* cannot be read" 30
check "modified: the run goes on" kill -0 $pid
sed -i 's/^endTime .*/endTime 0.001;/; s/^startTime .*/startTime 0.5;/' "$c/system/controlDict"
touch -d "@$stamp" "$c/system/controlDict"
waitExit $pid 60
check "modified: exit 0 once the new endTime is reached" [ $? -eq 0 ]
expectIn "modified: the new endTime applies" "$c/log" \
    "controlDict changed at time .*: now endTime 0.001 \(reached\), stopAt endTime \(changed: endTime\); read at the next start: startTime"
last=$(sed -n 's/^Writing time //p' "$c/log" | tail -1)
check "modified: wrote where it stopped ($last)" [ "$(timeDirs "$c")" = "0 $last " ]
expectIn "modified: End" "$c/log" "^End"

c=$(newCase notModifiable 's/^endTime .*/endTime 1;/; s/^writeInterval .*/writeInterval 0.05;/; s/^logInterval .*/logInterval 200;/; s/^stopAt .*/stopAt endTime; runTimeModifiable no;/')
sphVcpmFsi -case "$c" > "$c/log" 2>&1 &
pid=$!
waitFor "$c/log" "^Time = " 60
sed -i 's/^stopAt .*/stopAt noWriteNow; runTimeModifiable no;/' "$c/system/controlDict"
sleep 2
check "runTimeModifiable no: still running 2 s after the change" kill -0 $pid
waitExit $pid 300
check "runTimeModifiable no: exit 0" [ $? -eq 0 ]
check "runTimeModifiable no: controlDict not read again" \
    bash -c "! grep -q 'controlDict changed' '$c/log'"
check "runTimeModifiable no: ran to endTime" [ -d "$c/1" ]

# --- signals ---------------------------------------------------------------
# signalStop <name> <signal> <exit status>: a long run stopped by the
# signal writes its state, ends by the signal, and goes on from it.
signalStop()
{
    local c pid rc t
    c=$(newCase "$1" 's/^endTime .*/endTime 100;/; s/^writeInterval .*/writeInterval 10;/; s/^logInterval .*/logInterval 200;/')
    # A background job of a script has SIGINT ignored (and a run under
    # nohup SIGHUP), and the solver keeps them so: start it with the
    # default actions.
    python3 -c 'import os, signal, sys
signal.signal(signal.SIGINT, signal.SIG_DFL)
signal.signal(signal.SIGHUP, signal.SIG_DFL)
os.execvp(sys.argv[1], sys.argv[1:])' sphVcpmFsi -case "$c" > "$c/log" 2>&1 &
    pid=$!
    check "$1: the loop runs" waitFor "$c/log" "^Time = " 60
    # Twice at once, as timeout (the child, then its group) and a
    # terminal's Ctrl-C can deliver it: still one request.
    kill -s "$2" $pid; kill -s "$2" $pid
    waitExit $pid 60
    rc=$?
    check "$1: ends by the signal (exit $rc)" [ $rc -eq "$3" ]
    expectIn "$1: the signal is acknowledged as it comes" "$c/log" \
        "^--> Stop requested \\(SIG$2\\): the step in progress finishes, its state is written and the run stops"
    t=$(sed -n 's/^Stopped at time \([^ ]*\) on .*, time \([^ ]*\) written.*/\2/p' "$c/log")
    check "$1: wrote the state where it stopped ($t)" [ -n "$t" -a "$(timeDirs "$c")" = "0 $t " ]
    expectIn "$1: the log says how to go on" "$c/log" "startFrom latestTime goes on from it"
    expectIn "$1: the run summary is printed" "$c/log" "^Run summary: "
    sed -i "s/^endTime .*/endTime $(python3 -c "print($t + 0.002)");/" "$c/system/controlDict"
    sphVcpmFsi -case "$c" > "$c/log.restart" 2>&1
    check "$1: goes on from $t" [ $? -eq 0 ]
    expectIn "$1: read the stopped state" "$c/log.restart" "^Reading time $t"
}
signalStop sigterm TERM 143
signalStop sigint INT 130
signalStop sighup HUP 129

# A background job with SIGINT ignored keeps ignoring it, and a run under
# nohup its SIGHUP.
c=$(newCase ignored 's/^endTime .*/endTime 0.6;/; s/^writeInterval .*/writeInterval 0.3;/; s/^logInterval .*/logInterval 200;/')
nohup sphVcpmFsi -case "$c" > "$c/log" 2>&1 &
pid=$!
waitFor "$c/log" "^Time = " 60
check "an ignored SIGINT: running when it is sent" kill -s INT $pid
check "an ignored SIGHUP: running when it is sent" kill -s HUP $pid
waitExit $pid 300
check "ignored SIGINT and SIGHUP stay ignored: exit 0" [ $? -eq 0 ]
check "ignored SIGINT and SIGHUP stay ignored: ran to endTime" [ -d "$c/0.6" ]
check "ignored SIGINT and SIGHUP: no stop requested" \
    bash -c "! grep -q 'Stop requested' '$c/log'"
expectIn "an ignored SIGINT: the log says how to stop the run" "$c/log" \
    "SIGINT \\(Ctrl-C\\) is ignored, as it was when the run started .*: stop the run with kill -TERM $pid, or stopAt writeNow"

# One solver at a time in a case: a second one started beside a running
# one is an error naming it; -postProcess may run beside it.
c=$(newCase locked 's/^endTime .*/endTime 100;/; s/^writeInterval .*/writeInterval 10;/')
sphVcpmFsi -case "$c" > "$c/log" 2>&1 &
pid=$!
check "locked: the first run goes" waitFor "$c/log" "^Time = " 60
sphVcpmFsi -case "$c" > "$c/log.second" 2>&1
check "locked: a second run beside it: exit status 1" [ $? -eq 1 ]
expectIn "locked: the second run names the first" "$c/log.second" \
    "Another sphVcpmFsi \\(process $pid\\) is running in case .*kill -TERM $pid"
echo 'functions { beside { type energy; } }' > "$c/system/besideDict"
sphVcpmFsi -case "$c" -postProcess -latestTime -dict system/besideDict > "$c/log.post" 2>&1
check "locked: -postProcess beside it runs" grep -q '^End' "$c/log.post"
kill -TERM $pid; waitExit $pid 60
sphVcpmFsi -case "$c" > "$c/log.third" 2>&1 &
pid=$!
check "locked: once the first is gone (by a signal), a new run goes" waitFor "$c/log.third" "^Time = " 60
kill -9 $pid; wait $pid 2> /dev/null
sed -i 's/^endTime .*/endTime 0.002;/' "$c/system/controlDict"
sphVcpmFsi -case "$c" > "$c/log.fourth" 2>&1
check "locked: after a kill -9 no stale lock is left" grep -q '^End' "$c/log.fourth"

# A log that cannot be written (standard output on a full disk): the run
# ends with status 1 and says so on standard error, not 0 without its End.
c=$(newCase fullLog 's/^endTime .*/endTime 0.002;/')
sphVcpmFsi -case "$c" > /dev/full 2> "$c/log.err"
check "full log: exit status 1" [ $? -eq 1 ]
expectIn "full log: says so" "$c/log.err" "The log \\(standard output\\) could not be written in full"

# Other processes on the cores the threads need: said at the start of the
# loop, unless the threads wait passively (docs/solver.md, Threads). A
# busy loop per core makes sure of them. On the CPU: a GPU run's threads
# do little, and it says nothing.
c=$(newCase contention 's/^endTime .*/endTime 0.002;/')
cores=$(env -u OMP_NUM_THREADS -u OMP_THREAD_LIMIT nproc)   # nproc heeds them
busy=()
for ((i = 0; i < cores; ++i)); do
    bash -c 'end=$((SECONDS + 30)); while ((SECONDS < end)); do :; done' &
    busy+=($!)
done
env -u OMP_WAIT_POLICY OMP_NUM_THREADS=$cores sphVcpmFsi -device cpu -case "$c" > "$c/log" 2>&1
expectIn "busy cores: the log says the threads will contend" "$c/log" \
    "^Note: [0-9]+ other process(es)? running on the $cores cores: with $cores threads, .* OMP_NUM_THREADS=1 or OMP_WAIT_POLICY=passive avoid it"
rm -rf "$c"/0.0*
OMP_WAIT_POLICY=passive OMP_NUM_THREADS=$cores sphVcpmFsi -device cpu -case "$c" > "$c/log" 2>&1
check "busy cores, passive threads: no note" bash -c "! grep -q '^Note: .* other process' '$c/log'"
kill "${busy[@]}" 2> /dev/null; wait "${busy[@]}" 2> /dev/null

finish

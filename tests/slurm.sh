#!/bin/sh
# slurm.sh: a single-node Slurm (controller and node daemon on this
# machine, munge for authentication) for tests/tiles.sh's job array recipe.
#
# Usage: SLURM_CONF=DIR/slurm.conf sh tests/slurm.sh start DIR
#        SLURM_CONF=DIR/slurm.conf sh tests/slurm.sh stop DIR
# start writes DIR/slurm.conf, starts munged if no munge daemon answers,
# starts slurmctld and slurmd and waits (30 s at most) for the node to be
# idle; it fails, saying why on its last line, when the machine cannot run
# them (not root, daemons refused). stop stops what start started.

set -u
what=$1
DIR=$2
conf=${SLURM_CONF:-$DIR/slurm.conf}

case $what in
start)
    mkdir -p "$DIR/state" "$DIR/spool" "$DIR/log" || exit 1
    [ "$(id -u)" = 0 ] || { echo "not root: cannot start Slurm's daemons"; exit 1; }
    host=$(hostname -s)
    cpus=$(nproc)
    # Ports of our own, so that a Slurm already running here is not met.
    port=$((20000 + $$ % 20000))
    cat >"$conf" <<EOF
ClusterName=raytracetest
SlurmctldHost=$host
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
SlurmctldPort=$port
SlurmdPort=$((port + 1))
StateSaveLocation=$DIR/state
SlurmdSpoolDir=$DIR/spool
SlurmctldPidFile=$DIR/slurmctld.pid
SlurmdPidFile=$DIR/slurmd.pid
SlurmctldLogFile=$DIR/log/slurmctld.log
SlurmdLogFile=$DIR/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SlurmdParameters=config_overrides
ReturnToService=2
MpiDefault=none
JobCompType=jobcomp/none
AccountingStorageType=accounting_storage/none
NodeName=$host CPUs=$cpus State=UNKNOWN
PartitionName=test Nodes=$host Default=YES MaxTime=INFINITE State=UP
EOF
    if ! munge -n </dev/null 2>/dev/null | unmunge >/dev/null 2>&1; then
        if [ ! -s /etc/munge/munge.key ]; then
            mkdir -p /etc/munge
            dd if=/dev/urandom of=/etc/munge/munge.key bs=1024 count=1 2>/dev/null
            chown munge:munge /etc/munge/munge.key 2>/dev/null
            chmod 400 /etc/munge/munge.key
        fi
        mkdir -p /run/munge /var/log/munge /var/lib/munge
        chown munge:munge /run/munge /var/log/munge /var/lib/munge 2>/dev/null
        if command -v runuser >/dev/null 2>&1 && id munge >/dev/null 2>&1; then
            runuser -u munge -- munged >"$DIR/log/munged.out" 2>&1
        else
            munged --force >"$DIR/log/munged.out" 2>&1
        fi
        sleep 1
        munge -n </dev/null 2>/dev/null | unmunge >/dev/null 2>&1 ||
            { echo "munge does not work here: $(tail -n 1 "$DIR/log/munged.out")"; exit 1; }
        echo started >"$DIR/munged.ours"
    fi
    SLURM_CONF=$conf slurmctld >"$DIR/log/slurmctld.out" 2>&1 ||
        { echo "slurmctld refused to start: $(tail -n 1 "$DIR/log/slurmctld.out")"; exit 1; }
    SLURM_CONF=$conf slurmd >"$DIR/log/slurmd.out" 2>&1 ||
        { echo "slurmd refused to start: $(tail -n 1 "$DIR/log/slurmd.out")"; exit 1; }
    i=0
    while [ $i -lt 30 ]; do
        state=$(SLURM_CONF=$conf sinfo -h -o %t 2>/dev/null | head -n 1)
        case $state in idle*) echo "Slurm is up on $host"; exit 0 ;; esac
        sleep 1
        i=$((i + 1))
    done
    echo "the node did not come up within 30 s (state '$state'): $(tail -n 1 "$DIR/log/slurmd.log" 2>/dev/null)"
    exit 1
    ;;
stop)
    for d in slurmd slurmctld; do
        [ -s "$DIR/$d.pid" ] && kill "$(cat "$DIR/$d.pid")" 2>/dev/null
    done
    if [ -f "$DIR/munged.ours" ]; then
        pkill -x munged 2>/dev/null
    fi
    exit 0
    ;;
esac
echo "usage: sh tests/slurm.sh start|stop DIR" >&2
exit 2

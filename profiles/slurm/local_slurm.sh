#!/usr/bin/env bash
# A single-node SLURM on this machine, for proving profiles/slurm (make slurm-check).
#
#   profiles/slurm/local_slurm.sh install   apt packages: slurmctld, slurmd, munge (root)
#   profiles/slurm/local_slurm.sh start     write a slurm.conf under $SLURM_STATE and start
#                                           munged, slurmctld, slurmd; wait until the node is idle
#   profiles/slurm/local_slurm.sh stop      stop the three daemons
#
# The configuration goes to /etc/slurm/slurm.conf, where every client looks (srun inside a
# batch job ignores SLURM_CONF); an existing slurm.conf that is not ours is never
# overwritten. The daemons need no cgroups and no accounting database: ProctrackType
# linuxproc, TaskPlugin none, AccountingStorageType none. Snakemake's SLURM executor then
# cannot ask sacct, so the profile sets slurm-status-command: squeue, and MinJobAge (how
# long squeue still shows a finished job) is 600 s, well above the executor's status
# interval (at most 180 s) -- with a shorter MinJobAge a job can finish and vanish between
# two checks and Snakemake waits for it forever. Every step is bounded by a timeout.
set -euo pipefail

SLURM_STATE=${SLURM_STATE:-/tmp/randmedia-slurm}
CONF=/etc/slurm/slurm.conf
MARK="# written by randmedia profiles/slurm/local_slurm.sh"
HOST=$(hostname)

die() { echo "local_slurm: $*" >&2; exit 1; }

install() {
    [ "$(id -u)" = 0 ] || die "install needs root (apt-get)"
    if command -v slurmctld >/dev/null && command -v slurmd >/dev/null && command -v munged >/dev/null; then
        echo "local_slurm: slurmctld, slurmd, munged already installed"
        return
    fi
    export DEBIAN_FRONTEND=noninteractive
    timeout 300 apt-get update -q
    timeout 600 apt-get install -y -q slurmctld slurmd slurm-client munge
}

write_conf() {
    mkdir -p "$SLURM_STATE/ctld" "$SLURM_STATE/d" /etc/slurm
    if [ -e "$CONF" ] && ! grep -qF "$MARK" "$CONF"; then
        die "$CONF exists and is not ours: this script only runs SLURM on a machine without one"
    fi
    local cpus mem
    cpus=$(nproc)
    mem=$(awk '/MemTotal/ {printf "%d", $2 / 1024 * 0.9}' /proc/meminfo)
    cat > "$CONF" <<EOF
$MARK
ClusterName=randmedia
SlurmctldHost=$HOST(127.0.0.1)
AuthType=auth/munge
SlurmUser=root
SlurmdUser=root
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
StateSaveLocation=$SLURM_STATE/ctld
SlurmdSpoolDir=$SLURM_STATE/d
SlurmctldPidFile=$SLURM_STATE/slurmctld.pid
SlurmdPidFile=$SLURM_STATE/slurmd.pid
SlurmctldLogFile=$SLURM_STATE/slurmctld.log
SlurmdLogFile=$SLURM_STATE/slurmd.log
ReturnToService=2
MinJobAge=600
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core_Memory
AccountingStorageType=accounting_storage/none
JobAcctGatherType=jobacct_gather/none
MpiDefault=none
NodeName=$HOST NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=$mem State=UNKNOWN
PartitionName=main Nodes=$HOST Default=YES MaxTime=INFINITE State=UP
EOF
}

start() {
    command -v slurmctld >/dev/null || die "SLURM is not installed: run '$0 install' first"
    stop >/dev/null 2>&1 || true
    write_conf
    [ -s /etc/munge/munge.key ] || timeout 30 mungekey --create --force 2>/dev/null \
        || timeout 30 create-munge-key -f
    mkdir -p /run/munge
    chown munge:munge /run/munge 2>/dev/null || true
    pgrep -x munged >/dev/null || timeout 30 su -s /bin/sh munge -c "/usr/sbin/munged" \
        || timeout 30 /usr/sbin/munged --force
    timeout 30 slurmctld -f "$CONF"
    timeout 30 slurmd -f "$CONF" -N "$HOST"
    for _ in $(seq 1 60); do  # the node registers within a few seconds
        if sinfo -h -N -o "%T" 2>/dev/null | grep -qx idle; then
            echo "local_slurm: node $HOST idle ($CONF, state and logs in $SLURM_STATE)"
            return
        fi
        sleep 1
    done
    scontrol update nodename="$HOST" state=resume 2>/dev/null || true
    sinfo -h -N -o "%T" 2>/dev/null | grep -qx idle \
        || die "node $HOST did not become idle in 60 s (logs: $SLURM_STATE/*.log)"
}

stop() {
    for daemon in slurmd slurmctld; do
        pkill -x "$daemon" 2>/dev/null || true
    done
    for _ in $(seq 1 20); do
        pgrep -x slurmd >/dev/null || pgrep -x slurmctld >/dev/null || break
        sleep 0.5
    done
    pkill -9 -x slurmd 2>/dev/null || true
    pkill -9 -x slurmctld 2>/dev/null || true
    echo "local_slurm: stopped"
}

case "${1:-}" in
    install) install ;;
    start) start ;;
    stop) stop ;;
    *) die "usage: $0 install|start|stop" ;;
esac

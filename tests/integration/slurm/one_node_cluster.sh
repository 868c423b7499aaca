# A one-node Slurm cluster of our own, for the slurm tests (sourced; run inside `unshare -n`).
# Debian's slurm-wlm and munge: a private munged with a key of its own, slurmctld and slurmd in
# the foreground (-D) with a slurm.conf written here, every file under one temporary folder
# (short: munge's socket path has a length limit). cluster_up exports SLURM_CONF for the clients;
# cluster_down stops every job and daemon it started and removes the folder.
#   cluster_up CPUS     cluster_down [KEEP_LOGS_IN]
# (In a network namespace with only lo up, Slurm needs CommunicationParameters below; munged's socket
# folder must be mode 755.)

CLUSTER_DIR="" CLUSTER_PIDS=()

cluster_prerequisites() {  # prints what is missing
  local tool
  for tool in munged mungekey slurmctld slurmd sbatch squeue scontrol scancel sinfo; do
    command -v "$tool" >/dev/null || echo "$tool"
  done
}

cluster_up() {
  local cpus="$1" host state i
  host=$(hostname -s)
  CLUSTER_DIR=$(mktemp -d /tmp/sdlqr-slurm.XXXXXX)
  mkdir -p "$CLUSTER_DIR"/{munge,state,spool}
  chmod 755 "$CLUSTER_DIR" "$CLUSTER_DIR/munge"  # munged refuses a socket folder others can write
  mungekey --create --keyfile "$CLUSTER_DIR/munge.key" || return 1
  munged --key-file="$CLUSTER_DIR/munge.key" --socket="$CLUSTER_DIR/munge/socket" \
    --pid-file="$CLUSTER_DIR/munged.pid" --log-file="$CLUSTER_DIR/munged.log" --seed-file="$CLUSTER_DIR/munge.seed" ||
    return 1
  cat >"$CLUSTER_DIR/slurm.conf" <<CONF
# One node for the sdlqr slurm tests (tests/integration/slurm/one_node_cluster.sh)
ClusterName=sdlqr-test
SlurmctldHost=$host(127.0.0.1)
# Only lo is up in the test's namespace: IPv4 look-ups with AI_ADDRCONFIG ignore loopback, and
# Slurm hangs resolving 127.0.0.1 without this.
CommunicationParameters=EnableIPv4,EnableIPv6
AuthType=auth/munge
AuthInfo=socket=$CLUSTER_DIR/munge/socket
CredType=cred/munge
SlurmUser=root
SlurmdUser=root
ProctrackType=proctrack/pgid
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
StateSaveLocation=$CLUSTER_DIR/state
SlurmdSpoolDir=$CLUSTER_DIR/spool
SlurmctldPidFile=$CLUSTER_DIR/slurmctld.pid
SlurmdPidFile=$CLUSTER_DIR/slurmd.pid
SlurmctldLogFile=$CLUSTER_DIR/slurmctld.log
SlurmdLogFile=$CLUSTER_DIR/slurmd.log
MailProg=/bin/true
ReturnToService=2
NodeName=$host NodeAddr=127.0.0.1 CPUs=$cpus State=UNKNOWN
PartitionName=flights Nodes=ALL Default=YES MaxTime=INFINITE State=UP
CONF
  export SLURM_CONF="$CLUSTER_DIR/slurm.conf"
  slurmctld -D -f "$SLURM_CONF" >"$CLUSTER_DIR/slurmctld.out" 2>&1 &
  CLUSTER_PIDS+=($!)
  slurmd -D -f "$SLURM_CONF" >"$CLUSTER_DIR/slurmd.out" 2>&1 &
  CLUSTER_PIDS+=($!)
  for i in $(seq 300); do  # idle after ~1 s on a quiet machine
    state=$(sinfo --noheader --format=%T 2>/dev/null || true)
    [ "$state" = idle ] && return 0
    sleep 0.1
  done
  echo "one_node_cluster: the node is '$state', not idle, after 30 s" >&2
  return 1
}

cluster_down() {
  local keep="${1:-}" pid i
  [ -n "$CLUSTER_DIR" ] || return 0
  # Jobs first (their slurmstepd are not our children), then the daemons.
  scancel --full --user="$(id -un)" >/dev/null 2>&1 || true
  for i in $(seq 50); do
    [ -z "$(squeue --noheader --format=%i 2>/dev/null)" ] && break
    sleep 0.1
  done
  for pid in "${CLUSTER_PIDS[@]}"; do kill -TERM "$pid" 2>/dev/null || true; done
  for pid in "${CLUSTER_PIDS[@]}"; do wait "$pid" 2>/dev/null || true; done
  [ -f "$CLUSTER_DIR/munged.pid" ] && kill -TERM "$(cat "$CLUSTER_DIR/munged.pid")" 2>/dev/null || true
  if [ -n "$keep" ]; then
    mkdir -p "$keep"
    cp "$CLUSTER_DIR"/*.log "$CLUSTER_DIR"/*.out "$CLUSTER_DIR/slurm.conf" "$keep/" 2>/dev/null || true
  fi
  rm -rf "$CLUSTER_DIR"
  CLUSTER_DIR="" CLUSTER_PIDS=()
}

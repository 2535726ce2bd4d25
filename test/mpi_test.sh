#!/bin/sh
# smallmlt-mpi under mpirun on PoCL: a rank that cannot start stops every
# rank with messages naming ranks and hosts, and nothing hangs; --time stops
# every rank after the same pass; SIGINT to rank 0 stops every rank, rank 0
# writes the image so far and the job exits 3; bad command lines exit 2.
# (test_mpi.cpp checks the images.)
# Usage: mpi_test.sh [SMALLMLT_BIN] (runs smallmlt-mpi from the same folder)
set -u
MPI_BIN=$(dirname "${1:-build/smallmlt}")/smallmlt-mpi
DIR=build/test-scratch/mpi-sh
rm -rf "$DIR" && mkdir -p "$DIR"
. test/checks.sh
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
# (mpirun passes its stdin to rank 0: give it none)
MPIRUN="timeout 120 mpirun --oversubscribe --stdin none"
SMALL="scenes/cornell.scene --width 16 --height 16 --threads 256 --burn-in-iters 2"

# says TEXT: the last command's output ($out) contains TEXT (a regex)
says() { printf '%s' "$out" | grep -q -- "$1"; }
# failed_in_time: $rc is a failure, not the timeout's 124
failed_in_time() { [ "$rc" -ne 0 ] && [ "$rc" -ne 124 ]; }
# one_value WORDS: all the words are the same number
one_value() { [ -n "$1" ] && [ "$(echo "$1" | tr ' ' '\n' | sort -u | wc -l)" -eq 1 ]; }

truth built [ -x "$MPI_BIN" ]
# Rank 1 finds no OpenCL platform (an empty vendors folder, on any ICD):
# both ranks exit non-zero, naming rank and host.
mkdir -p "$DIR/no-vendors"
out=$($MPIRUN -np 1 "$MPI_BIN" render $SMALL --spp 1 --out "$DIR/fail.pfm" : \
    -np 1 env OCL_ICD_VENDORS="$DIR/no-vendors" "$MPI_BIN" render $SMALL --spp 1 \
    --out "$DIR/fail.pfm" 2>&1)
rc=$?
truth rank_failure_exit failed_in_time
truth rank_failure_names_rank says "rank 1 on $(hostname).*: no OpenCL platform found"
truth rank_failure_stops_others says "rank 0 on $(hostname).*: stopped, as another rank failed to start"
absent rank_failure_no_file "$DIR/fail.pfm"
check bad_flag 2 "unknown option --fast" -- $MPIRUN -np 2 "$MPI_BIN" render scenes/cornell.scene --fast
check log_refused 2 "--log $DIR/l.csv: one process only" -- $MPIRUN -np 2 "$MPI_BIN" render $SMALL --spp 1 --reference "$DIR/none.pfm" --log "$DIR/l.csv"
check device_range 2 "--device: index 7 out of range" -- $MPIRUN -np 2 "$MPI_BIN" render $SMALL --spp 1 --device 7 --out "$DIR/dev.pfm"
# --time: every rank stops after the same pass.
out=$($MPIRUN -np 3 "$MPI_BIN" render $SMALL --time 0.8 --out "$DIR/time.pfm" 2>&1)
rc=$?
truth time_exit [ "$rc" -eq 0 ]
passes=$(printf '%s' "$out" | sed -n 's/.*passes per rank \([0-9 ]*\),.*/\1/p')
truth time_same_pass one_value "$passes"
truth time_image [ -s "$DIR/time.pfm" ]
# SIGINT to rank 0 alone, once rank 0 says every rank is set up: every rank
# stops after its pass, rank 0 writes, the job exits 3.
$MPIRUN -np 2 "$MPI_BIN" render $SMALL --time 60 --out "$DIR/int.pfm" > "$DIR/int.log" 2>&1 &
job=$!
rank0=""
for _ in $(seq 1 600); do
    for p in $(pgrep -f "smallmlt-mpi render $SMALL --time 60"); do
        tr '\0' '\n' < "/proc/$p/environ" 2>/dev/null | grep -qx 'OMPI_COMM_WORLD_RANK=0' && rank0=$p
    done
    [ -n "$rank0" ] && grep -q "; rendering" "$DIR/int.log" && break
    sleep 0.1
done
[ -n "$rank0" ] && kill -INT "$rank0"
wait "$job"
rc=$?
truth sigint_exit_3 [ "$rc" -eq 3 ]
truth sigint_image [ -s "$DIR/int.pfm" ]
truth sigint_message grep -q "interrupted after" "$DIR/int.log"
summary mpi

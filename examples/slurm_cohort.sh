#!/bin/bash
#SBATCH --job-name=pfdm --array=0-49 --cpus-per-task=2 --time=02:00:00
# A cohort as a Slurm array: each task fits its shard of cases.csv into
# fits/ (finished cases are skipped, so a task resubmitted after a kill
# resumes).  sbatch slurm_cohort.sh from the folder of cases.csv; then, when
# the array is done, the whole cohort's summary:
#   sbatch --dependency=afterany:<jobid> --wrap \
#     "pfdm batch --manifest cases.csv --out fits"
# scripts/slurm_check.sh runs this file on a one-node Slurm (CTest
# CohortRunsOnSlurm).
pfdm batch --manifest cases.csv --out fits --jobs 2 \
  --shard "$SLURM_ARRAY_TASK_ID/$SLURM_ARRAY_TASK_COUNT"

#!/bin/bash
# Filters a long input as a Slurm array job, one task per chunk, then the
# chunk videos are joined losslessly. Submit with:
#   eyestream chunks -i drive/frames/%05d.exr -o chunks/chunk_%03d.mp4 \
#       --chunk-frames 1800 --preroll 10 -- -g drive/gaze.csv > chunks.txt
#   sbatch --array=1-$(wc -l < chunks.txt) samples/slurm-chunks.sh chunks.txt
# Each task runs line $SLURM_ARRAY_TASK_ID of the command file.
#SBATCH --job-name=eyestream-chunks
#SBATCH --cpus-per-task=2
#SBATCH --mem=4G
#SBATCH --time=02:00:00
set -euo pipefail
commands=${1:?usage: sbatch --array=1-N slurm-chunks.sh COMMAND_FILE}
line=$(sed -n "${SLURM_ARRAY_TASK_ID}p" "$commands")
[ -n "$line" ] || { echo "no command $SLURM_ARRAY_TASK_ID in $commands" >&2; exit 2; }
eval "$line --no-progress"

#!/usr/bin/env bash
# Off-screen recording of a scenario run: rviz under Xvfb, captured by ffmpeg (x11grab).
# Usage: rviz/record.sh SCENARIO [PLANNER] [RATE]
#   SCENARIO  name in asv_bringup/scenarios (without .yaml)
#   PLANNER   aco | dssa | dssa_plus | mopso | ga | "" (the scenario's own, default)
#   RATE      simulation real-time factor (default 20)
# Environment: RECORD_ARGS: more scenario.launch arguments (e.g. "max_sim_time:=1800").
# The mouse pointer is not drawn. Leaves out/SCENARIO/LABEL/{result.json,run.bag} and out/SCENARIO/LABEL.mp4 + .png (the final frame),
# LABEL being the planner or "scenario". Needs a built workspace (make build) and xvfb, ffmpeg, rviz
# (scripts/setup installs them).
set -uo pipefail
cd "$(dirname "$0")/.."
if [[ $# -lt 1 || "$1" == "-h" || "$1" == "--help" ]]; then sed -n 2,9p "$0" | sed 's/^# \{0,1\}//'; exit 0; fi
scenario=$1
planner=${2:-}
rate=${3:-20}
label=${planner:-scenario}
out="$PWD/out/$scenario"
mkdir -p "$out/$label"
export PATH=/usr/bin:$PATH ROS_HOSTNAME=localhost ROS_LOG_DIR="$PWD/build/ros_log"
set +u  # the ROS environment scripts read unset variables
# shellcheck disable=SC1091
source devel/setup.bash
set -u
display=:$((90 + RANDOM % 9))
Xvfb "$display" -screen 0 1280x720x24 -nolisten tcp > "$out/xvfb.log" 2>&1 &
xvfb=$!
trap 'kill $xvfb 2>/dev/null' EXIT
sleep 1
export DISPLAY=$display
# Software rendering: there is no GPU on these machines.
export LIBGL_ALWAYS_SOFTWARE=1
roslaunch asv_bringup scenario.launch scenario:="$scenario" planner:="$planner" rate:="$rate" \
  rviz:=true record:=true out:="$out/$label" ${RECORD_ARGS:-} > "$out/$label/launch.log" 2>&1 &
launch=$!
sleep 6  # rviz needs a few seconds to open its window
ffmpeg -nostdin -loglevel error -y -f x11grab -draw_mouse 0 -video_size 1280x720 -framerate 10 -i "$display" \
  -c:v libx264 -preset veryfast -pix_fmt yuv420p "$out/$label.mp4" &
ffmpeg_pid=$!
wait $launch
status=$?
kill -INT $ffmpeg_pid 2>/dev/null
wait $ffmpeg_pid 2>/dev/null
# The last second shows rviz closing: the final frame of the run is a few seconds before the end.
ffmpeg -nostdin -loglevel error -y -sseof -4 -i "$out/$label.mp4" -frames:v 1 "$out/$label.png" || true
echo "record: video $out/$label.mp4, last frame $out/$label.png, bag $out/$label/run.bag, result $out/$label/result.json"
exit $status

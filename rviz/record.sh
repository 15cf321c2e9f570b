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
# Whatever ends the script, nothing it started is left running.
launch="" rviz_pid="" ffmpeg_pid=""
trap 'kill $launch $rviz_pid $ffmpeg_pid $xvfb 2>/dev/null' EXIT
sleep 1
export DISPLAY=$display
# Software rendering: there is no GPU on these machines.
export LIBGL_ALWAYS_SOFTWARE=1
# rviz starts once sim_node has loaded the scenario and set /sim/scene_box (where the encounter takes place):
# its view is fitted to that box (map frame, not following the own ship), so that the last frame shows
# the whole encounter. The simulation waits start_delay wall seconds for it.
rosparam delete /sim/scene_box > /dev/null 2>&1 || true  # a master already up may hold an older run's
roslaunch asv_bringup scenario.launch scenario:="$scenario" planner:="$planner" rate:="$rate" \
  start_delay:=15 record:=true out:="$out/$label" ${RECORD_ARGS:-} > "$out/$label/launch.log" 2>&1 &
launch=$!
box=""
for _ in $(seq 1 100); do
  box=$(rosparam get /sim/scene_box 2>/dev/null) && break
  sleep 0.1
done
config="$out/$label/rviz.rviz"
# The view: centred on the box, the scale [px/m] that fits it; no Displays panel. /view_scale sizes the
# nodes' markers in pixels at that scale.
scale=$(python3 - "$box" "$config" <<'PYEOF'
import re, sys
box = [float(v) for v in re.findall(r"-?[0-9.]+(?:e[-+]?[0-9]+)?", sys.argv[1])]
text = open("asv_bringup/rviz/asv.rviz").read()
text = re.sub(r"^Panels:\n(?:  .*\n)*", "Panels: []\n", text, flags=re.M)
scale = 0.06
if len(box) == 4:
    x0, y0, x1, y1 = box
    scale = 0.95 * min(1280.0 / max(x1 - x0, 1.0), 690.0 / max(y1 - y0, 1.0))  # 30 px of toolbar
    text = text.replace("Target Frame: own/base_link", "Target Frame: <Fixed Frame>")
    text = re.sub(r"Scale: [0-9.]+", "Scale: %.6f" % scale, text, count=1)
    text = re.sub(r"(Name: Current View(?:\n.*)*?\n      X: )0\n      Y: 0",
                  lambda m: m.group(1) + "%.1f\n      Y: %.1f" % ((x0 + x1) / 2, (y0 + y1) / 2), text, count=1)
open(sys.argv[2], "w").write(text)
print("%.6f" % scale)
PYEOF
)
[ -n "$box" ] || echo "record: no /sim/scene_box: the view follows the own ship" >&2
rosparam set /view_scale "${scale:-0.06}"
ROS_NAMESPACE=own rviz -d "$config" > "$out/rviz.log" 2>&1 &
rviz_pid=$!
sleep 8  # rviz needs a few seconds to open its window
ffmpeg -nostdin -loglevel error -y -f x11grab -draw_mouse 0 -video_size 1280x720 -framerate 10 -i "$display" \
  -c:v libx264 -preset veryfast -pix_fmt yuv420p "$out/$label.mp4" &
ffmpeg_pid=$!
wait $launch
status=$?
sleep 3  # rviz keeps the run's last markers: three seconds of the summary frame
kill -INT $ffmpeg_pid 2>/dev/null
wait $ffmpeg_pid 2>/dev/null
kill $rviz_pid 2>/dev/null
ffmpeg -nostdin -loglevel error -y -sseof -1 -i "$out/$label.mp4" -frames:v 1 "$out/$label.png" || true
echo "record: video $out/$label.mp4, last frame $out/$label.png, bag $out/$label/run.bag, result $out/$label/result.json"
exit $status

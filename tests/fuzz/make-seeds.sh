#!/usr/bin/env bash
# Regenerates the seed corpora tests/fuzz/corpus/<reader>/ from small inputs the project makes
# itself, with the release apps (cmake --build --preset release first):
#   tests/fuzz/make-seeds.sh
# Seeds are small (the fuzzer's input size limit follows the largest seed). Inputs of the log
# and .gridmap harnesses start with a flag byte: '1' = the harness gzips the rest.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
bin="$root/build/release/bin"
corpus="$here/corpus"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
seed() {  # seed <reader> <name> <flag or ""> <file...>: concatenates flag + files
    local reader=$1 name=$2 flag=$3
    shift 3
    mkdir -p "$corpus/$reader"
    { printf '%s' "$flag"; cat "$@"; } >"$corpus/$reader/$name"
}
rm -rf "$corpus"

# --- CARMEN: FLASER (old format) with PARAM and ODOM; ROBOTLASER1 -------------------------
python3 - "$tmp" <<'PY'
import sys
d = sys.argv[1]
with open(f"{d}/flaser.clf", "w") as f:
    f.write("# TopoSLAM fuzz seed\nPARAM robot_front_laser_max 30.0 nohost 0\n"
            "PARAM laser_front_laser_resolution 1.0 nohost 0\n")
    for i in range(3):
        t = 10.0 + 0.1 * i
        x = 0.1 * i
        f.write(f"ODOM {x} 0 0 0.1 0 0 {t:.6f} nohost {t:.6f}\n")
        ranges = " ".join(f"{2.0 + 0.1 * b:.2f}" for b in range(12))
        f.write(f"FLASER 12 {ranges} {x} 0 0 {x} 0 0 {t:.6f} nohost {t:.6f}\n")
with open(f"{d}/robotlaser.clf", "w") as f:
    for i in range(2):
        t = 20.0 + 0.1 * i
        ranges = " ".join(f"{3.0 + 0.05 * b:.2f}" for b in range(9))
        f.write(f"ROBOTLASER1 0 -1.5708 3.1416 0.3927 50.0 0.01 0 9 {ranges} 0 "
                f"0.22 0 0 0 0 0 0 0 0 0 0 {t:.6f} nohost {t:.6f}\n")
PY
seed carmen flaser "0" "$tmp/flaser.clf"
seed carmen flaser_gz "1" "$tmp/flaser.clf"
seed carmen robotlaser "0" "$tmp/robotlaser.clf"
for f in flaser_wrap5.clf robotlaser_wrap.clf; do seed carmen "finding_$f" "0" "$here/findings/$f"; done

# --- rawlogs: both formats, annotated (features + bearing range) ----------------------------
"$bin/toposlam-convert" -q "$tmp/flaser.clf" -o "$tmp/obs.rawlog"
"$bin/toposlam-convert" -q "$tmp/flaser.clf" -o "$tmp/sf.rawlog" --format sf
"$bin/toposlam-annotate-features" -q "$tmp/flaser.clf" -o "$tmp/annotated.rawlog" --bearing-range
seed rawlog obs "0" "$tmp/obs.rawlog"
seed rawlog obs_gz "1" "$tmp/obs.rawlog"
seed rawlog sf "0" "$tmp/sf.rawlog"
seed rawlog annotated "0" "$tmp/annotated.rawlog"
for f in rawlog_crash.rawlog oom-4b998fc9.rawlog oom-00091269.rawlog; do
    seed rawlog "finding_$f" "0" "$here/findings/$f"
done

# --- grid maps: a 16 x 12 map with walls, free space, unknown cells -------------------------
python3 - "$tmp" <<'PY'
import sys
d = sys.argv[1]
w, h = 16, 12
px = bytearray()
for y in range(h):
    for x in range(w):
        wall = x in (0, w - 1) or y in (0, h - 1)
        px.append(0 if wall else (205 if x > 11 else 254))
open(f"{d}/map.pgm", "wb").write(b"P5\n%d %d\n255\n" % (w, h) + bytes(px))
open(f"{d}/map.yaml", "w").write("image: map.pgm\nresolution: 0.05\norigin: [-0.4, -0.3, 0]\n"
                                  "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n")
PY
"$bin/toposlam-convert" -q "$tmp/map.yaml" -o "$tmp/map.gridmap"
"$bin/toposlam-convert" -q "$tmp/map.yaml" -o "$tmp/pic.png"
seed gridmap plain "0" "$tmp/map.gridmap"
seed gridmap gz "1" "$tmp/map.gridmap"
seed gridmap finding_oom-8df72e38.gridmap "0" "$here/findings/oom-8df72e38.gridmap"
nul="$tmp/nul"
printf '\0' >"$nul"
# PNG picture with its sidecar: the ROS pair written with it, and an old-style scale sidecar.
sed 's/pic.pgm/map.pgm/' "$tmp/pic.yaml" >"$tmp/pair.yaml"
seed gridmap_image pair "" "$tmp/pair.yaml" "$nul" "$tmp/pic.png"
sed -e 's/pic.pgm/map.png/' -e 's/trinary/scale/' "$tmp/pic.yaml" >"$tmp/scale.yaml"
seed gridmap_image scale "" "$tmp/scale.yaml" "$nul" "$tmp/pic.png"
# ROS pairs in every mode.
sed 's/map.pgm/ros.pgm/' "$tmp/map.yaml" >"$tmp/ros.yaml"
seed ros_map trinary "" "$tmp/ros.yaml" "$nul" "$tmp/map.pgm"
{ sed 's/negate: 0/negate: 1/' "$tmp/ros.yaml"; echo "mode: scale"; } >"$tmp/ros_scale.yaml"
seed ros_map negate_scale "" "$tmp/ros_scale.yaml" "$nul" "$tmp/map.pgm"
{ cat "$tmp/ros.yaml"; echo "mode: raw"; } >"$tmp/ros_raw.yaml"
seed ros_map raw "" "$tmp/ros_raw.yaml" "$nul" "$tmp/map.pgm"
seed ros_map finding_hang-pct86 "" "$here/findings/hang-pct86.yaml" "$nul" "$tmp/map.pgm"

# --- topological maps: two rooms and a door, segmented by toposlam-rooms ---------------------
python3 - "$tmp" <<'PY'
import sys
d = sys.argv[1]
w, h = 48, 24
px = bytearray()
for y in range(h):
    for x in range(w):
        wall = x in (0, w - 1) or y in (0, h - 1) or (x == 24 and not 10 <= y < 14)
        px.append(0 if wall else 254)
open(f"{d}/rooms.pgm", "wb").write(b"P5\n%d %d\n255\n" % (w, h) + bytes(px))
open(f"{d}/rooms.yaml", "w").write("image: rooms.pgm\nresolution: 0.1\norigin: [0, 0, 0]\n"
                                    "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n")
PY
"$bin/toposlam-rooms" "$tmp/rooms.yaml" -o "$tmp/rooms-out" >/dev/null
seed rooms_json two_rooms "" "$tmp/rooms-out/rooms.json"
seed rooms_graphml two_rooms "" "$tmp/rooms-out/rooms.graphml"
for f in deep_nesting_32k.json json_bad_u_escape.json; do seed rooms_json "finding_$f" "" "$here/findings/$f"; done

# --- relations, trajectories, .ini files ---------------------------------------------------
printf '# t1 t2 x y z roll pitch yaw\n10.0 10.1 0.1 0 0 0 0 0.01\n10.2 10.0 -0.2 0.01 0 0 0 -0.02\n' >"$tmp/r"
seed relations small "" "$tmp/r"
printf '# timestamp x y yaw\n10.0 0 0 0\n10.1 0.1 0 0.01\n10.2 0.2 0.01 0.02\n' >"$tmp/t"
seed trajectory small "" "$tmp/t"
for f in "$root"/config_ini/*.ini; do seed ini "$(basename "$f" .ini)" "" "$f"; done
ls -l "$corpus"/*

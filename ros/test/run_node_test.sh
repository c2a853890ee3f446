#!/usr/bin/env bash
# The ROS node test (ctest ros_node): a real rosmaster on a free loopback port, projsurf_node
# twice (on demand, started by roslaunch with ros/launch/projsurf.launch; continuous, started
# directly), and the C++ test client. Every wait is bounded; everything started here is
# stopped on exit, whatever happens.
# usage: run_node_test.sh ROS_BUILD_DIR TEST_CLIENT PROJSURF_CLI
# (PROJSURF_NODE_TEST_KEEP=DIR: on failure, everything written, ROS logs too, is copied there.)
set -euo pipefail
build=$1 client=$2
tmp=$(mktemp -d /tmp/projsurf-ros-test.XXXXXX)
pids=()

stop_all() {
    local pid i
    # Interrupt first (roslaunch stops its nodes), give them up to 10 s, then kill.
    for pid in "${pids[@]}"; do kill -INT "$pid" 2>/dev/null || true; done
    for i in $(seq 100); do
        local alive=0
        for pid in "${pids[@]}"; do kill -0 "$pid" 2>/dev/null && alive=1; done
        [ $alive = 0 ] && break
        sleep 0.1
    done
    for pid in "${pids[@]}"; do kill -KILL "$pid" 2>/dev/null || true; done
    for pid in "${pids[@]}"; do wait "$pid" 2>/dev/null || true; done
}
on_exit() {
    local rc=$?
    stop_all
    if [ $rc != 0 ]; then
        for f in "$tmp"/*.log; do echo "----- $f (tail)"; tail -n 30 "$f"; done
        # The whole of it (the master's and every node's ROS logs too), to look into a flake.
        if [ -n "${PROJSURF_NODE_TEST_KEEP:-}" ]; then
            mkdir -p "$PROJSURF_NODE_TEST_KEEP" && cp -r "$tmp" "$PROJSURF_NODE_TEST_KEEP/" &&
                echo "run_node_test: logs kept in $PROJSURF_NODE_TEST_KEEP/$(basename "$tmp")"
        fi
    fi
    rm -rf "$tmp"
    exit $rc
}
trap on_exit EXIT
trap 'exit 130' INT TERM

# A free TCP port on loopback (the kernel picks it; a tiny race with other programs remains,
# so the master's start is checked and retried on another port).
free_port() {
    local p
    for _ in $(seq 50); do
        p=$(( (RANDOM % 20000) + 30000 ))
        if ! (exec 3<>"/dev/tcp/127.0.0.1/$p") 2>/dev/null; then echo "$p"; return; fi
    done
    echo "run_node_test: no free port found" >&2
    return 1
}

export ROS_HOSTNAME=127.0.0.1
unset ROS_IP ROS_NAMESPACE
export ROS_HOME="$tmp/home" ROS_LOG_DIR="$tmp/rlog"
export ROS_PACKAGE_PATH="$build"
export PROJSURF_TEST_TMP="$tmp"

started=0
for attempt in 1 2 3; do
    port=$(free_port)
    export ROS_MASTER_URI="http://127.0.0.1:$port"
    rosmaster --core -p "$port" >"$tmp/master.log" 2>&1 &
    master=$!
    if "$client" --wait-for-master 20 >/dev/null 2>&1; then
        pids+=("$master")
        started=1
        break
    fi
    kill -KILL "$master" 2>/dev/null || true
    wait "$master" 2>/dev/null || true
done
[ $started = 1 ] || { echo "run_node_test: rosmaster did not start"; exit 1; }
echo "run_node_test: rosmaster at $ROS_MASTER_URI"

"$client" --write-calibration "$tmp/calib.yaml"

# ~config: a bad settings file stops the node at start with one line naming the file and the
# key (exit 2); a good one (projsurf detect --print-config's keys) starts it.
printf 'planes:\n  max_plane: 6\n' >"$tmp/bad_config.yaml"
set +e
timeout 30 "$build/projsurf_node" __ns:=/badconfig __name:=projsurf _calib:="$tmp/calib.yaml" \
    _config:="$tmp/bad_config.yaml" >"$tmp/bad_config_node.log" 2>&1
rc=$?
set -e
[ $rc = 2 ] || { echo "run_node_test: ~config with an unknown key exited $rc, expected 2"; exit 1; }
grep -qF "$tmp/bad_config.yaml: unknown key 'planes.max_plane' (did you mean 'planes.max_planes'?)" \
    "$tmp/bad_config_node.log" || { echo "run_node_test: ~config's error does not name the key"; exit 1; }
printf 'method: paper\nplanes: {max_planes: 3}\n' >"$tmp/good_config.yaml"
# With a parameter the paper method ignores (~max_planes) and one it uses (~hull): the CLI's warning.
stdbuf -oL "$build/projsurf_node" __ns:=/goodconfig __name:=projsurf _calib:="$tmp/calib.yaml" \
    _config:="$tmp/good_config.yaml" _max_planes:=4 _hull:=convex \
    >"$tmp/good_config_node.log" 2>&1 &  # line-buffered: read while it runs
good=$!
pids+=("$good")
for _ in $(seq 200); do
    grep -q "projsurf_node: projector" "$tmp/good_config_node.log" && break
    kill -0 "$good" 2>/dev/null || break
    sleep 0.1
done
grep -q "projsurf_node: projector" "$tmp/good_config_node.log" ||
    { echo "run_node_test: the node did not start with a good ~config"; exit 1; }
grep -qF "~max_planes is ignored by the paper method" "$tmp/good_config_node.log" ||
    { echo "run_node_test: no warning for ~max_planes, which the paper method ignores"; exit 1; }
if grep -qF "~hull is ignored" "$tmp/good_config_node.log"; then
    echo "run_node_test: ~hull warned as ignored, but the paper method uses it"; exit 1
fi
kill -INT "$good" 2>/dev/null || true
echo "run_node_test: ~config read (bad file refused naming the key, good file accepted; ~max_planes warned as ignored)"

# On demand, through the launch file (as a user starts it).
ROS_NAMESPACE=/oneshot roslaunch projsurf projsurf.launch calib:="$tmp/calib.yaml" \
    >"$tmp/roslaunch.log" 2>&1 &
pids+=($!)
# Continuous mode with tf: the picture is kept put in odom, gravity comes from odom's -z.
"$build/projsurf_node" __ns:=/moving __name:=projsurf _calib:="$tmp/calib.yaml" _continuous:=true \
    _fixed_frame:=odom _gravity_frame:=odom _tf_timeout:=0.5 >"$tmp/continuous_node.log" 2>&1 &
pids+=($!)

# Continuous mode, standing still: blanking what walks into the beam.
"$build/projsurf_node" __ns:=/still __name:=projsurf _calib:="$tmp/calib.yaml" _continuous:=true \
    >"$tmp/still_node.log" 2>&1 &
pids+=($!)

# Registered colour, continuous so that ~result has each frame's frame_ms; and the
# same node without colour (today's behaviour) on the same frames.
"$build/projsurf_node" __ns:=/colour __name:=projsurf _calib:="$tmp/calib.yaml" _continuous:=true \
    _use_colour:=true >"$tmp/colour_node.log" 2>&1 &
pids+=($!)
# ~voxel_leaf: a paper-method setting the default method ignores, warned about at the start.
"$build/projsurf_node" __ns:=/plain __name:=projsurf _calib:="$tmp/calib.yaml" _continuous:=true \
    _voxel_leaf:=0.02 >"$tmp/plain_node.log" 2>&1 &
pids+=($!)

# ~explain: ~result carries every candidate plane and why it lost, on demand and continuous.
"$build/projsurf_node" __ns:=/explain __name:=projsurf _calib:="$tmp/calib.yaml" _explain:=true \
    >"$tmp/explain_node.log" 2>&1 &
pids+=($!)
"$build/projsurf_node" __ns:=/explain_continuous __name:=projsurf _calib:="$tmp/calib.yaml" _continuous:=true \
    _explain:=true >"$tmp/explain_continuous_node.log" 2>&1 &
pids+=($!)

export PROJSURF_EXPLAIN_NS=/explain PROJSURF_EXPLAIN_CONTINUOUS_NS=/explain_continuous
export PROJSURF_ONESHOT_NS=/oneshot PROJSURF_MOVING_NS=/moving PROJSURF_STILL_NS=/still
export PROJSURF_COLOUR_NS=/colour PROJSURF_PLAIN_NS=/plain
timeout --signal=INT --kill-after=10 240 "$client" --gtest_filter='NodeTest.*:ColourNodeTest.*'
grep -qF "~voxel_leaf is ignored by the default method" "$tmp/plain_node.log" ||
    { echo "run_node_test: no warning for ~voxel_leaf, which the default method ignores"; exit 1; }

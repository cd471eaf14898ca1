#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
# Dynamic-environment ice through pvserver: pvpython renders the scene in one process, then
# connects to a pvserver on 127.0.0.1 (a free port) and renders it on the server (remote
# rendering) and on the client (client-side rendering); both must equal the one-process image
# (Python/client_server_scene.py, Python/compare_client_server.py).
set -euo pipefail
pvserver=$1 pvpython=$2 out=$3
here=$(dirname "$0")
"$pvpython" "$here/Python/client_server_scene.py" builtin "$out/client-server-builtin.png"
run() { # [--bind-address=127.0.0.1]: the server, then the client
  local port
  port=$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
  "$pvserver" "$@" --server-port="$port" --timeout=5 >"$out/client-server-pvserver.log" 2>&1 &
  local server=$!
  # The server is ready when it says so.
  for _ in $(seq 100); do
    grep -q "Accepting connection" "$out/client-server-pvserver.log" && break
    kill -0 "$server" 2>/dev/null || break
    sleep 0.2
  done
  local status=0
  "$pvpython" "$here/Python/client_server_scene.py" "$port" \
    "$out/client-server-remote.png" "$out/client-server-local.png" || status=$?
  wait "$server" || status=$?
  cat "$out/client-server-pvserver.log"
  return "$status"
}
if "$pvserver" --help 2>&1 | grep -q -- --bind-address; then
  run --bind-address=127.0.0.1
else
  # ParaView 5.11's pvserver has no --bind-address (it listens on every interface): the server
  # and the client run in a network namespace of their own, whose only interface is the loopback.
  export -f run
  export pvserver pvpython out here
  unshare --net bash -c 'python3 -c "
import fcntl, socket, struct
# SIOCSIFFLAGS, IFF_UP: the loopback up.
fcntl.ioctl(socket.socket(), 0x8914, struct.pack(\"16sh14x\", b\"lo\", 1))" && run'
fi
"$pvpython" "$here/Python/compare_client_server.py" "$out/client-server-builtin.png" \
  "$out/client-server-remote.png" "$out/client-server-local.png"

"""Runs a ParaView client against a parallel server on this machine: starts
`MPIEXEC -n RANKS PVSERVER` listening on a free port of the loopback interface, waits until it
accepts connections, runs `PVPYTHON SCRIPT --connect=127.0.0.1:PORT ARGS...`, and returns the
client's status (a server that fails or does not end after the client disconnects fails too).

    python3 client_server.py MPIEXEC RANKS PVSERVER PVPYTHON SCRIPT [ARGS...]
"""
import os
import socket
import subprocess
import sys
import threading

mpiexec, ranks, pvserver, pvpython, script = sys.argv[1:6]
arguments = sys.argv[6:]

with socket.socket() as probe:
    probe.bind(("127.0.0.1", 0))
    port = probe.getsockname()[1]

server = subprocess.Popen(
    [mpiexec, "--oversubscribe", "-n", ranks, pvserver, "--server-port=%d" % port,
     "--hostname=127.0.0.1"],
    stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
ready = threading.Event()
log = []


def follow():
    for line in server.stdout:
        log.append(line)
        if "Accepting connection" in line:
            ready.set()
    ready.set()  # the server ended


threading.Thread(target=follow, daemon=True).start()
status = 1
try:
    if not ready.wait(120) or server.poll() is not None:
        print("FAILED: the server did not start")
    else:
        # pvpython finds its own modules; the same modules on PYTHONPATH (which pvserver and
        # pvbatch need) would be loaded twice and crash it.
        environment = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
        client = subprocess.run([pvpython, script, "--connect=127.0.0.1:%d" % port] + arguments,
                                env=environment, timeout=300)
        status = client.returncode
        # The server ends when its client disconnects.
        if server.wait(timeout=60) != 0:
            print("FAILED: the server ended with status %d" % server.returncode)
            status = status or 1
except subprocess.TimeoutExpired as timeout:
    print("FAILED: %s did not end in %d s" % (timeout.cmd[0], timeout.timeout))
finally:
    if server.poll() is None:
        server.kill()
        server.wait()
    print("server output:\n" + "".join(log))
sys.exit(status)

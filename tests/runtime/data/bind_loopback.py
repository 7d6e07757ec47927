"""Runs rosbridge_websocket (ROS 1) bound to 127.0.0.1 only; under Debian's /usr/bin/python3.

rosbridge_server 0.11 calls autobahn's listenWS without an interface, so its --address only
names the URL and the server listens on every network interface. This wrapper passes
interface="127.0.0.1" to listenWS and then runs the unmodified script.
Usage: bind_loopback.py ROSBRIDGE_WEBSOCKET_SCRIPT [ARGS...]
"""

import runpy
import sys

import autobahn.twisted.websocket as websocket

_listen = websocket.listenWS


def _listen_on_loopback(factory, contextFactory=None, backlog=50, interface=""):
    return _listen(factory, contextFactory, backlog, interface="127.0.0.1")


websocket.listenWS = _listen_on_loopback
script = sys.argv[1]
sys.argv = sys.argv[1:]
runpy.run_path(script, run_name="__main__")

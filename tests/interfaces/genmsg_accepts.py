"""Print, for each ROS 1 text given as JSON on stdin, whether genmsg accepts it.

Runs under Debian's /usr/bin/python3 (where python3-genmsg lives). Input: a JSON list of
``{"kind": "msg"|"srv", "package": ..., "name": ..., "text": ...}``. Output: a JSON list, one
entry per input: ``"accept"``, ``"refuse"`` (genmsg's own errors: InvalidMsgSpec, ValueError)
or ``"undefined"`` (genmsg failed some other way, such as an IndexError on a malformed line).
"""

import json
import sys

import genmsg
import genmsg.msg_loader as loader


def verdict(item):
    context = loader.MsgContext.create_default()
    full_name = f"{item['package']}/{item['name']}"
    load = loader.load_msg_from_string if item["kind"] == "msg" else loader.load_srv_from_string
    try:
        spec = load(context, item["text"], full_name)
        # A field type genmsg reads but cannot resolve (pkg/msg/Name) fails when it is loaded.
        parts = [spec] if item["kind"] == "msg" else [spec.request, spec.response]
        for part in parts:
            for base in {genmsg.msgs.bare_msg_type(t) for t in part.types}:
                if "/" in base:
                    genmsg.package_resource_name(base)
    except (genmsg.InvalidMsgSpec, ValueError):
        return "refuse"
    except Exception:  # anything else is behaviour genmsg does not define
        return "undefined"
    return "accept"


def main():
    items = json.load(sys.stdin)
    json.dump([verdict(item) for item in items], sys.stdout)


if __name__ == "__main__":
    main()

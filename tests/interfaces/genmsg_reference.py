"""Print genmsg's md5sum and full text for every ROS 1 msg and srv under a share folder, as JSON.

Runs under Debian's /usr/bin/python3 (where python3-genmsg lives), not the project's Python:
the tests call it in a subprocess so that the reference values come from genmsg itself.
Usage: /usr/bin/python3 genmsg_reference.py /usr/share
"""

import glob
import json
import os
import sys

import genmsg.msg_loader as loader
from genmsg import gentools


def main(root):
    packages = sorted(
        {
            os.path.basename(os.path.dirname(d))
            for d in glob.glob(root + "/*/msg") + glob.glob(root + "/*/srv")
        }
    )
    search = {p: [os.path.join(root, p, "msg")] for p in packages}
    context = loader.MsgContext.create_default()
    result = {}
    for package in packages:
        for path in sorted(glob.glob(os.path.join(root, package, "msg", "*.msg"))):
            name = f"{package}/{os.path.basename(path)[:-4]}"
            spec = loader.load_msg_by_type(context, name, search)
            loader.load_depends(context, spec, search)
            result[name] = {
                "md5sum": gentools.compute_md5(context, spec),
                "definition": gentools.compute_full_text(context, spec),
            }
        for path in sorted(glob.glob(os.path.join(root, package, "srv", "*.srv"))):
            name = f"{package}/{os.path.basename(path)[:-4]}"
            spec = loader.load_srv_from_file(context, path, name)
            loader.load_depends(context, spec, search)
            halves = {}
            for key, half in (("request", spec.request), ("response", spec.response)):
                halves[key] = {
                    "type": half.full_name,
                    "md5sum": gentools.compute_md5(context, half),
                    "definition": gentools.compute_full_text(context, half),
                }
            result[name] = dict(md5sum=gentools.compute_md5(context, spec), **halves)
    json.dump(result, sys.stdout, indent=0, sort_keys=True)


if __name__ == "__main__":
    main(sys.argv[1])

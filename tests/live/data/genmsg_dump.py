"""Print genmsg's md5sum and full text of the named ROS 1 types, as JSON.

Runs under Debian's /usr/bin/python3 (python3-genmsg). Packages are looked up in the folders
given with --root (each holding <pkg>/msg and <pkg>/srv), then in /usr/share.
Usage: genmsg_dump.py --root DIR ... TYPE ...   (a TYPE ending in .srv names a service)
"""

import argparse
import glob
import json
import os
import sys

import genmsg.msg_loader as loader
from genmsg import gentools


def search_path(roots):
    found = {}
    for root in [*roots, "/usr/share"]:
        for folder in sorted(glob.glob(os.path.join(root, "*", "msg"))):
            found.setdefault(os.path.basename(os.path.dirname(folder)), []).append(folder)
    return found


def describe(context, spec):
    return {
        "type": spec.full_name,
        "md5sum": gentools.compute_md5(context, spec),
        "definition": gentools.compute_full_text(context, spec),
        "typedefs": typedefs(context, spec),
    }


def typedef(spec):
    """rosapi's TypeDef of one message (constants sorted by name, as rosapi lists them)."""
    fields = spec.parsed_fields()
    constants = sorted(spec.constants, key=lambda c: c.name)
    return {
        "type": spec.full_name,
        "fieldnames": [f.name for f in fields],
        "fieldtypes": [f.base_type for f in fields],
        "fieldarraylen": [-1 if not f.is_array else (f.array_len or 0) for f in fields],
        "examples": ["{}" if not f.is_builtin else "0" for f in fields],
        "constnames": [c.name for c in constants],
        "constvalues": [str(c.val) for c in constants],
    }


def typedefs(context, spec):
    """The root's TypeDef, then one per nested type, depth first, each once."""
    found, order = {}, []

    def walk(current):
        for field in current.parsed_fields():
            if field.is_builtin or field.base_type in found:
                continue
            nested = context.get_registered(field.base_type)
            found[field.base_type] = nested
            order.append(nested)
            walk(nested)

    walk(spec)
    return [typedef(spec)] + [typedef(s) for s in order]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--root", action="append", default=[])
    parser.add_argument("types", nargs="+")
    args = parser.parse_args()
    search = search_path(args.root)
    context = loader.MsgContext.create_default()
    result = {}
    for name in args.types:
        if name.endswith(".srv"):
            name = name[:-4]
            package, short = name.split("/")
            path = next(
                p
                for root in [*args.root, "/usr/share"]
                for p in [os.path.join(root, package, "srv", short + ".srv")]
                if os.path.exists(p)
            )
            spec = loader.load_srv_from_file(context, path, name)
            loader.load_depends(context, spec, search)
            result[name] = {
                "md5sum": gentools.compute_md5(context, spec),
                "request": describe(context, spec.request),
                "response": describe(context, spec.response),
            }
        else:
            spec = loader.load_msg_by_type(context, name, search)
            loader.load_depends(context, spec, search)
            result[name] = describe(context, spec)
    json.dump(result, sys.stdout, indent=1, sort_keys=True)


if __name__ == "__main__":
    main()

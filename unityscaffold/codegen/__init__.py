"""C# generation: ROS interfaces -> message, service and action classes for a Unity runtime.

One target today, Siemens' ROS# (``targets.ROSSHARP``); text comes from the jinja2 templates in
``templates/<target>/``. Everything here is pure: it returns files, it never writes them.
"""

from unityscaffold.codegen.generate import GeneratedFile, Generation, Options, SkippedClass, generate

__all__ = ["GeneratedFile", "Generation", "Options", "SkippedClass", "generate"]

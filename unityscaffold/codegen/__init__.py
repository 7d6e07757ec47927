"""C# generation: ROS interfaces -> message, service and action classes for a Unity runtime.

One target today, Siemens' ROS# (templates in the package's ``templates/rossharp/``); everything
here is pure: it returns files and the ROS-type-to-class map, it never writes.
"""

from unityscaffold.codegen.generate import (
    GeneratedCode,
    GeneratedFile,
    Options,
    SkippedClass,
    generate,
)
from unityscaffold.codegen.roles import ClassRole

__all__ = ["ClassRole", "GeneratedCode", "GeneratedFile", "Options", "SkippedClass", "generate"]

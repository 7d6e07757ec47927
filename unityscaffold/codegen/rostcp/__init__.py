"""C# generation for Unity's ROS-TCP-Connector (v0.7): ROS interfaces -> its message classes.

The one entry point::

    generate(registry, roots, Options(dialect, include_shipped=False, namespace=None))
        -> GeneratedCode

takes what the ROS# generator (``unityscaffold.codegen.generate``) takes and returns the same
``GeneratedCode``: ``files`` (paths relative to the output folder, such as
``Geometry/msg/PoseMsg.cs``), ``skipped`` (the classes the connector ships and the generated code
references instead, each with a ``warning`` when the shipped class does not match the distro's
definition, or never registers itself: the connector's ROS 1 action wrappers), and ``classes``
(ROS type -> C# class per ``ClassRole``, for the scripts). So ``codegen.layout.output_files``
places the files and their ``.meta`` files as for ROS#.

Classes have the connector's public shape and names: ``RosMessageTypes.<Pkg>.<Name>Msg`` with
public fields, ``k_RosMessageName`` (``pkg/Name`` in both ROS versions), ``Deserialize``,
``SerializeTo``, ``ToString`` and ``Register``; a service gives ``<Srv>Request`` and
``<Srv>Response`` (registered as ``pkg/Srv``, the response under ``MessageSubtopic.Response``);
a ROS 1 action gives ``XGoal``, ``XResult``, ``XFeedback`` (registered as ``pkg/XGoal`` …), the
wrappers ``XActionGoal``, ``XActionResult``, ``XActionFeedback`` on the connector's generic
bases, and ``XAction``. Each file is guarded by ``#if ROS2`` or ``#if !ROS2``, as for ROS#.

Refused with a ``UserError``: ROS 2 actions (ROS-TCP-Endpoint cannot carry them),
``include_shipped`` (the connector registers one class per ROS name, so a second class for a
shipped name would race it), two classes registering one ROS name, ``wstring`` fields.
``namespace`` replaces the root ``RosMessageTypes`` for generated classes; shipped ones stay
where the package has them.
"""

from unityscaffold.codegen.rostcp.generate import generate

__all__ = ["generate"]

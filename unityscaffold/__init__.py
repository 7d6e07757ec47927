"""unityscaffold: ROS interfaces and a YAML manifest in, a wired ROS# Unity project out.

Stages: ``manifest`` → ``interfaces`` → ``codegen`` / ``unity`` → ``apply``; ``cli`` is a thin
typer layer over them. See docs/architecture.md.
"""

__version__ = "0.1.0"

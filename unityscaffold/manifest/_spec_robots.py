"""The key table's section for ``robots:`` entries (a URDF imported into a scene)."""

from __future__ import annotations

from unityscaffold.manifest._keys import (
    BOOL,
    FLOAT32_MAX,
    GAMEOBJECT_VALUE,
    NOT_PORTABLE,
    NOT_RELATIVE,
    STR,
    Key,
    Section,
    scene_key,
)

__all__ = ["ENV_NAME", "ROBOT", "URDF_SUFFIX"]

URDF_SUFFIX = "[.](urdf|xacro)$"
# what xacro can name in $(env VAR): it splits a substitution at spaces and ends it at ')'
ENV_NAME = r"^[^\s()$]+$"
_FLOAT = {"type": "number", "minimum": -FLOAT32_MAX, "maximum": FLOAT32_MAX}
_VEC3 = {"type": "array", "items": _FLOAT, "minItems": 3, "maxItems": 3}
_ASSETS = {
    "type": "string",
    "pattern": "^Assets/[^/]+(/[^/]+)*$",
    "not": {"pattern": NOT_RELATIVE},
}

ROBOT = Section(
    "robot",
    "robot",
    "A robot imported from its URDF as ROS#'s importer does it, and kept as the URDF says.",
    (
        Key(
            "urdf",
            "The robot's `.urdf` file, relative to the manifest, or a `.xacro` (`.urdf.xacro`) "
            "expanded in process (needs `pip install 'unityscaffold[xacro]'`).",
            {"type": "string", "pattern": URDF_SUFFIX, "not": {"pattern": NOT_PORTABLE}},
            required=True,
        ),
        Key(
            "gameobject",
            "Hierarchy path of the robot's root GameObject (`World/r2d2` puts it under "
            "`World`). Default: the robot's name in the URDF.",
            GAMEOBJECT_VALUE,
        ),
        scene_key("robot"),
        Key(
            "packages",
            "Folders of the ROS packages that `package://` and `$(find)` name, relative to "
            "the manifest (`{urdf_tutorial: ros/urdf_tutorial}`). A package not listed is "
            "looked for beside the URDF, as ROS# does.",
            {"type": ["object", "null"], "additionalProperties": STR},
        ),
        Key(
            "args",
            "Arguments of a `.xacro` `urdf`, name to text (`{prefix: left_}`); an argument "
            "left out takes its `<xacro:arg>` default.",
            {"type": ["object", "null"], "additionalProperties": STR},
        ),
        Key(
            "env",
            "Environment variables of a `.xacro` `urdf`, name to text "
            "(`{HUSKY_LMS1XX_ENABLED: '1'}`): what its `$(env VAR)` and `$(optenv VAR default)` "
            "read. The machine's environment is never read: a variable left out takes its "
            "`$(optenv)` default (empty without one), and `$(env)` of it is an error.",
            {
                "type": ["object", "null"],
                "propertyNames": {"pattern": ENV_NAME},
                "additionalProperties": {"type": "string"},
            },
        ),
        Key(
            "assets",
            "Folder inside Assets/ for the robot's materials and meshes. "
            "Default: `Assets/Urdf/<robot name>`.",
            _ASSETS,
        ),
        Key("position", "Local position of the robot's root `[x, y, z]`.", _VEC3),
        Key(
            "rotation",
            "Local rotation of the robot's root as Euler angles in degrees `[x, y, z]`.",
            _VEC3,
        ),
        Key(
            "kinematic",
            "UrdfRobot's *Is Kinematic*: every link's Rigidbody `m_IsKinematic`. "
            "Left out: `false`, as the importer makes them.",
            BOOL,
        ),
        Key(
            "gravity",
            "UrdfRobot's *Use Gravity*: every link's Rigidbody `m_UseGravity`. "
            "Left out: `true`, as the importer makes them.",
            BOOL,
        ),
        Key(
            "convex",
            "UrdfRobot's *Convex*: every collision MeshCollider's `m_Convex`. "
            "Left out: as the importer makes them (a cylinder's collider is convex).",
            BOOL,
        ),
        Key(
            "plugin_newline",
            "Line ends of the UrdfPlugin texts: `crlf` as ROS#'s importer writes them on "
            "Windows, or `lf`.",
            {"enum": ["crlf", "lf"]},
            default="crlf",
        ),
    ),
)

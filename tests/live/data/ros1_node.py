"""A rospy node for the discovery tests; runs under Debian's /usr/bin/python3.

Its message classes are built at run time with genpy.dynamic from genmsg's full texts (given as
the JSON file genmsg_dump.py writes), so custom types need no generated Python package.
Publishes /chatter, /imu and /reading, subscribes to /cmd_vel, serves /trigger and /calibrate.
With actionlib (Debian's python3-actionlib and its own actionlib/TwoInts and actionlib/Test
actions): serves the action /two_ints and is a client, without a server, of /served_by_unity.
Usage: ros1_node.py DEFINITIONS.json
"""

import json
import sys

import actionlib
import actionlib.msg
import genpy.dynamic
import rospy


def message_class(definitions, name):
    entry = definitions[name]
    return genpy.dynamic.generate_dynamic(entry["type"], entry["definition"])[entry["type"]]


def service_class(definitions, name):
    entry = definitions[name]
    _package, short = name.split("/")
    request = genpy.dynamic.generate_dynamic(
        entry["request"]["type"], entry["request"]["definition"]
    )
    response = genpy.dynamic.generate_dynamic(
        entry["response"]["type"], entry["response"]["definition"]
    )
    return type(
        short,
        (object,),
        {
            "_type": name,
            "_md5sum": entry["md5sum"],
            "_request_class": request[entry["request"]["type"]],
            "_response_class": response[entry["response"]["type"]],
        },
    )


def main(path):
    with open(path) as handle:
        definitions = json.load(handle)
    rospy.init_node("scaffold_test_node", disable_signals=True)
    string = message_class(definitions, "std_msgs/String")
    imu = message_class(definitions, "sensor_msgs/Imu")
    reading = message_class(definitions, "scaffold_test_msgs/Reading")
    twist = message_class(definitions, "geometry_msgs/Twist")
    publishers = [
        rospy.Publisher("/chatter", string, queue_size=1),
        rospy.Publisher("/imu", imu, queue_size=1),
        rospy.Publisher("/reading", reading, queue_size=1),
    ]
    rospy.Subscriber("/cmd_vel", twist, lambda message: None)
    trigger = service_class(definitions, "std_srvs/Trigger")
    calibrate = service_class(definitions, "scaffold_test_msgs/Calibrate")
    rospy.Service("/trigger", trigger, lambda request: trigger._response_class(True, "ok"))
    rospy.Service(
        "/calibrate", calibrate, lambda request: calibrate._response_class(True, "calibrated")
    )
    two_ints = actionlib.SimpleActionServer(
        "/two_ints",
        actionlib.msg.TwoIntsAction,
        lambda goal: two_ints.set_succeeded(actionlib.msg.TwoIntsResult(sum=goal.a + goal.b)),
        auto_start=False,
    )
    two_ints.start()
    actionlib.SimpleActionClient("/served_by_unity", actionlib.msg.TestAction)
    messages = [string(data="hello"), imu(), reading()]
    print("ready", flush=True)
    while not rospy.is_shutdown():
        for publisher, message in zip(publishers, messages, strict=True):
            publisher.publish(message)
        rospy.sleep(0.2)


if __name__ == "__main__":
    main(sys.argv[1])

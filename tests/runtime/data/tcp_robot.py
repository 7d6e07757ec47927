"""The ROS side of the connector scenario, a rospy node: echoes /chatter on /echo, serves
/trigger (std_srvs/Trigger) and the action /map (nav_msgs/GetMap, actionlib), then calls Unity's
/set (std_srvs/SetBool) and sends a goal to Unity's action /sim/map once they are there,
printing "set SUCCESS MESSAGE" and "map_result STATE FRAME_ID"."""

import actionlib
import rospy
from nav_msgs.msg import GetMapAction, GetMapResult
from std_msgs.msg import String
from std_srvs.srv import SetBool, Trigger, TriggerResponse

rospy.init_node("robot")
echo = rospy.Publisher("/echo", String, queue_size=10)
rospy.Subscriber("/chatter", String, lambda m: echo.publish(String("echo: " + m.data)))
rospy.Service("/trigger", Trigger, lambda _: TriggerResponse(True, "triggered"))
maps = actionlib.SimpleActionServer("/map", GetMapAction, auto_start=False)


def serve_map(_goal):
    result = GetMapResult()
    result.map.header.frame_id = "map-from-ros"
    result.map.info.width = 3
    maps.set_succeeded(result)


maps.register_goal_callback(lambda: serve_map(maps.accept_new_goal()))
maps.start()
while not rospy.is_shutdown():
    try:
        rospy.wait_for_service("/set", timeout=1.0)
        answer = rospy.ServiceProxy("/set", SetBool)(True)
        print("set", answer.success, answer.message, flush=True)
        break
    except (rospy.ROSException, rospy.ServiceException) as error:
        print("waiting for /set:", error, flush=True)
        rospy.sleep(0.5)
client = actionlib.SimpleActionClient("/sim/map", GetMapAction)
while not rospy.is_shutdown() and not client.wait_for_server(rospy.Duration(1.0)):
    print("waiting for /sim/map", flush=True)
client.send_goal(GetMapAction().action_goal.goal)
if client.wait_for_result(rospy.Duration(20.0)):
    print("map_result", client.get_state(), client.get_result().map.header.frame_id, flush=True)
else:
    print("map_result none", flush=True)
rospy.spin()

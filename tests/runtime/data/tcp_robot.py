"""The ROS side of the connector scenario, a rospy node: echoes /chatter on /echo, serves
/trigger (std_srvs/Trigger), and calls Unity's /set (std_srvs/SetBool) once it is advertised,
printing "set SUCCESS MESSAGE"."""

import rospy
from std_msgs.msg import String
from std_srvs.srv import SetBool, Trigger, TriggerResponse

rospy.init_node("robot")
echo = rospy.Publisher("/echo", String, queue_size=10)
rospy.Subscriber("/chatter", String, lambda m: echo.publish(String("echo: " + m.data)))
rospy.Service("/trigger", Trigger, lambda _: TriggerResponse(True, "triggered"))
while not rospy.is_shutdown():
    try:
        rospy.wait_for_service("/set", timeout=1.0)
        answer = rospy.ServiceProxy("/set", SetBool)(True)
        print("set", answer.success, answer.message, flush=True)
        break
    except (rospy.ROSException, rospy.ServiceException) as error:
        print("waiting for /set:", error, flush=True)
        rospy.sleep(0.5)
rospy.spin()

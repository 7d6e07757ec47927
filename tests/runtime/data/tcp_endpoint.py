"""ROS-TCP-Endpoint (ROS 1) on a loopback port, as its default_server_endpoint starts it but
bound to 127.0.0.1 (its default is every interface). Usage: tcp_endpoint.py PORT"""

import sys

import rospy
from ros_tcp_endpoint import TcpServer

rospy.init_node("unity_endpoint")
TcpServer(rospy.get_name(), tcp_ip="127.0.0.1", tcp_port=int(sys.argv[1])).start()
rospy.spin()

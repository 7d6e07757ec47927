// Your code for OdomSubscriber (subscriber of /odom).
// Created once by unityscaffold and never rewritten: edit freely. The generated half of this
// class is OdomSubscriber.cs.
using UnityEngine;

namespace RosGenerated
{
    public partial class OdomSubscriber
    {
        partial void OnMessage(global::RosSharp.RosBridgeClient.MessageTypes.Nav.Odometry message)
        {
            // Runs on Unity's main thread: safe to use Unity objects here.
        }
    }
}

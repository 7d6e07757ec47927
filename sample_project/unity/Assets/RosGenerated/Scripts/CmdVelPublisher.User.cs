// Your code for CmdVelPublisher (publisher of /cmd_vel).
// Created once by unityscaffold and never rewritten: edit freely. The generated half of this
// class is CmdVelPublisher.cs.
using UnityEngine;

namespace RosGenerated
{
    public partial class CmdVelPublisher
    {
        partial void UpdateMessage(global::RosSharp.RosBridgeClient.MessageTypes.Geometry.Twist message)
        {
            // Fill in the message before each timed publish, or call Publish(message) yourself.
        }
    }
}

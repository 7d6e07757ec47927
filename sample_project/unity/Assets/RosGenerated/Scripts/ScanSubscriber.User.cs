// Your code for ScanSubscriber (subscriber of /scan).
// Created once by unityscaffold and never rewritten: edit freely. The generated half of this
// class is ScanSubscriber.cs.
using UnityEngine;

namespace RosGenerated
{
    public partial class ScanSubscriber
    {
        partial void OnMessage(global::RosSharp.RosBridgeClient.MessageTypes.Sensor.LaserScan message)
        {
            // Runs on Unity's main thread: safe to use Unity objects here.
        }
    }
}

// Your code for EchoSubscriber (subscriber of /echo).
// Created once by unityscaffold and never rewritten: edit freely. The generated half of this
// class is EchoSubscriber.cs.
using UnityEngine;

namespace RosGenerated
{
    public partial class EchoSubscriber
    {
        partial void OnMessage(global::RosMessageTypes.Std.StringMsg message)
        {
            // Runs on Unity's main thread: safe to use Unity objects here.
        }
    }
}

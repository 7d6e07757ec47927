// Your code for BaseStatusSubscriber (subscriber of /base_status).
// Created once by unityscaffold and never rewritten: edit freely. The generated half of this
// class is BaseStatusSubscriber.cs.
using UnityEngine;

namespace RosGenerated
{
    public partial class BaseStatusSubscriber
    {
        partial void OnMessage(global::RosMessageTypes.Diffbot.BaseStatusMsg message)
        {
            // Runs on Unity's main thread: safe to use Unity objects here.
        }
    }
}

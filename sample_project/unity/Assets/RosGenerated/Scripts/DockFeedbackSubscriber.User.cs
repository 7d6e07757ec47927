// Your code for DockFeedbackSubscriber (subscriber of /dock/feedback).
// Created once by unityscaffold and never rewritten: edit freely. The generated half of this
// class is DockFeedbackSubscriber.cs.
using UnityEngine;

namespace RosGenerated
{
    public partial class DockFeedbackSubscriber
    {
        partial void OnMessage(global::RosSharp.RosBridgeClient.MessageTypes.Diffbot.DockActionFeedback message)
        {
            // Runs on Unity's main thread: safe to use Unity objects here.
        }
    }
}

// Your code for ResetClient (client of /reset).
// Created once by unityscaffold and never rewritten: edit freely. The generated half of this
// class is ResetClient.cs.
using UnityEngine;

namespace RosGenerated
{
    public partial class ResetClient
    {
        partial void OnResponse(global::RosSharp.RosBridgeClient.MessageTypes.Std.TriggerResponse response)
        {
            // Runs on Unity's main thread. Send requests with Call(new TriggerRequest()).
        }
    }
}

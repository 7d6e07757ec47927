// Your code for TriggerClient (client of /trigger).
// Created once by unityscaffold and never rewritten: edit freely. The generated half of this
// class is TriggerClient.cs.
using UnityEngine;

namespace RosGenerated
{
    public partial class TriggerClient
    {
        partial void OnResponse(global::RosMessageTypes.Std.TriggerResponse response)
        {
            // Runs on Unity's main thread. Send requests with Call(new TriggerRequest()).
        }
    }
}

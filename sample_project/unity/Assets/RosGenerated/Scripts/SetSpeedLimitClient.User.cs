// Your code for SetSpeedLimitClient (client of /set_speed_limit).
// Created once by unityscaffold and never rewritten: edit freely. The generated half of this
// class is SetSpeedLimitClient.cs.
using UnityEngine;

namespace RosGenerated
{
    public partial class SetSpeedLimitClient
    {
        partial void OnResponse(global::RosSharp.RosBridgeClient.MessageTypes.Diffbot.SetSpeedLimitResponse response)
        {
            // Runs on Unity's main thread. Send requests with Call(new SetSpeedLimitRequest()).
        }
    }
}

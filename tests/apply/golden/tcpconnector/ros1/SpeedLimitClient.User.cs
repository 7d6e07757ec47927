// Your code for SpeedLimitClient (client of /speed_limit).
// Created once by unityscaffold and never rewritten: edit freely. The generated half of this
// class is SpeedLimitClient.cs.
using UnityEngine;

namespace RosGenerated
{
    public partial class SpeedLimitClient
    {
        partial void OnResponse(global::RosMessageTypes.Diffbot.SetSpeedLimitResponse response)
        {
            // Runs on Unity's main thread. Send requests with Call(new SetSpeedLimitRequest()).
        }
    }
}

// Your code for DockActionClient (client of the action /dock).
// Created once by unityscaffold and never rewritten: edit freely. The generated half of this
// class is DockActionClient.cs.
using UnityEngine;

namespace RosGenerated
{
    public partial class DockActionClient
    {
        partial void OnFeedback(string goalId, global::RosMessageTypes.Diffbot.DockFeedback feedback)
        {
            // Runs on Unity's main thread. Send goals with SendGoal(new DockGoal()).
        }

        partial void OnResult(string goalId, byte status, global::RosMessageTypes.Diffbot.DockResult result)
        {
            // Runs on Unity's main thread, once per goal; status is one of RosMessageTypes.Actionlib.GoalStatusMsg's.
        }
    }
}

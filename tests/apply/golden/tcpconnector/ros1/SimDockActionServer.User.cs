// Your code for SimDockActionServer (server of the action /sim/dock).
// Created once by unityscaffold and never rewritten: edit freely. The generated half of this
// class is SimDockActionServer.cs.
using UnityEngine;

namespace RosGenerated
{
    public partial class SimDockActionServer
    {
        partial void OnGoal(string goalId, global::RosMessageTypes.Diffbot.DockGoal goal, ref bool accept)
        {
            // Runs on Unity's main thread. Work on the goal (here or over frames), PublishFeedback
            // as it goes, and end it with SetSucceeded, SetAborted or SetCanceled(goalId, result).
        }

        partial void OnCancel(string goalId)
        {
            // Runs on Unity's main thread: stop the goal's work and call SetCanceled(goalId, result).
        }
    }
}

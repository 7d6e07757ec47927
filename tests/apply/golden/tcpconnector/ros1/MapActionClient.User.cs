// Your code for MapActionClient (client of the action /map).
// Created once by unityscaffold and never rewritten: edit freely. The generated half of this
// class is MapActionClient.cs.
using UnityEngine;

namespace RosGenerated
{
    public partial class MapActionClient
    {
        partial void OnFeedback(string goalId, global::RosMessageTypes.Nav.GetMapFeedback feedback)
        {
            // Runs on Unity's main thread. Send goals with SendGoal(new GetMapGoal()).
        }

        partial void OnResult(string goalId, byte status, global::RosMessageTypes.Nav.GetMapResult result)
        {
            // Runs on Unity's main thread, once per goal; status is one of RosMessageTypes.Actionlib.GoalStatusMsg's.
        }
    }
}

// Your code for ResetServer (server of /reset).
// Created once by unityscaffold and never rewritten: edit freely. The generated half of this
// class is ResetServer.cs.
using UnityEngine;

namespace RosGenerated
{
    public partial class ResetServer
    {
        partial void HandleRequest(global::RosMessageTypes.Std.EmptyRequest request, global::RosMessageTypes.Std.EmptyResponse response, ref bool success)
        {
            // Runs on Unity's main thread: fill in the response.
        }
    }
}

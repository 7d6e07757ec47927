// Your code for SetServer (server of /set).
// Created once by unityscaffold and never rewritten: edit freely. The generated half of this
// class is SetServer.cs.
using UnityEngine;

namespace RosGenerated
{
    public partial class SetServer
    {
        partial void HandleRequest(global::RosMessageTypes.Std.SetBoolRequest request, global::RosMessageTypes.Std.SetBoolResponse response, ref bool success)
        {
            // Runs on Unity's main thread: fill in the response.
        }
    }
}

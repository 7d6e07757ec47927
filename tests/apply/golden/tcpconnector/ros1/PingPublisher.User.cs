// Your code for PingPublisher (publisher of /ping).
// Created once by unityscaffold and never rewritten: edit freely. The generated half of this
// class is PingPublisher.cs.
using UnityEngine;

namespace RosGenerated
{
    public partial class PingPublisher
    {
        partial void UpdateMessage(global::RosMessageTypes.Std.EmptyMsg message)
        {
            // Fill in the message before each timed publish, or call Publish(message) yourself.
        }
    }
}

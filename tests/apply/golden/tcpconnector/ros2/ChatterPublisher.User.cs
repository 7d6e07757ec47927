// Your code for ChatterPublisher (publisher of /chatter).
// Created once by unityscaffold and never rewritten: edit freely. The generated half of this
// class is ChatterPublisher.cs.
using UnityEngine;

namespace RosGenerated
{
    public partial class ChatterPublisher
    {
        partial void UpdateMessage(global::RosMessageTypes.Std.StringMsg message)
        {
            // Fill in the message before each timed publish, or call Publish(message) yourself.
        }
    }
}

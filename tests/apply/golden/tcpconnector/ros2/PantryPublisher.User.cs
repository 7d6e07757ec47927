// Your code for PantryPublisher (publisher of /pantry).
// Created once by unityscaffold and never rewritten: edit freely. The generated half of this
// class is PantryPublisher.cs.
using UnityEngine;

namespace RosGenerated
{
    public partial class PantryPublisher
    {
        partial void UpdateMessage(global::RosMessageTypes.TcpTest.PantryMsg message)
        {
            // Fill in the message before each timed publish, or call Publish(message) yourself.
        }
    }
}

// Test-only replacement for ROS#'s Serializers/MicrosoftSerializer.cs, compiled instead of it.
// ROS#'s file needs System.Memory (Span/Memory), which Debian's Mono 6.8 does not ship and no
// package registry reachable from CI carries; RosSocket names the class in its serializer table,
// so the client does not compile without a class of this name. Every test uses
// SerializerEnum.Newtonsoft_JSON; choosing Microsoft here fails loudly instead of silently.
using System;

namespace RosSharp.RosBridgeClient
{
    class MicrosoftSerializer : ISerializer
    {
        public byte[] Serialize<T>(T obj) { throw Unavailable(); }
        public DeserializedObject Deserialize(byte[] buffer) { throw Unavailable(); }
        public T Deserialize<T>(string json) { throw Unavailable(); }

        static Exception Unavailable()
        {
            return new NotSupportedException("System.Text.Json needs System.Memory, missing from Debian's Mono");
        }
    }
}

// The members of UnityEngine that ROS-TCP-Connector's message runtime (Runtime/MessageGeneration
// and Runtime/Messages) and the generated message classes use, with Unity's signatures; nothing
// else. MessageRegistry.Register warns on a second registration of one ROS name: the warning is
// kept, so a test can see it.
namespace UnityEngine
{
    public static class Debug
    {
        public static readonly System.Collections.Generic.List<string> Warnings =
            new System.Collections.Generic.List<string>();

        public static void LogWarning(object message)
        {
            Warnings.Add(message.ToString());
        }
    }

    [System.AttributeUsage(System.AttributeTargets.Method, AllowMultiple = false)]
    public sealed class RuntimeInitializeOnLoadMethodAttribute : System.Attribute
    {
    }
}

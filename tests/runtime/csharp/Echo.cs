// Test program: with ROS#'s real client, subscribe to each input topic and republish every
// message received, unchanged (the deserialized object itself), on its output topic.
// Usage: mono Echo.exe WS_URL PLAN_FILE, where each PLAN_FILE line is "IN OUT CSharpClass".
// Prints "ready" once every subscription and advertisement is sent; exits when stdin closes.
using System;
using System.IO;
using System.Linq;
using System.Reflection;
using RosSharp.RosBridgeClient;
using RosSharp.RosBridgeClient.Protocols;

public static class Echo
{
    public static Type FindType(string fullName)
    {
        foreach (Assembly assembly in AppDomain.CurrentDomain.GetAssemblies())
        {
            Type type = assembly.GetType(fullName);
            if (type != null)
            {
                return type;
            }
        }
        throw new ArgumentException("no class " + fullName);
    }

    public static int Main(string[] args)
    {
        foreach (string dll in Directory.GetFiles(AppDomain.CurrentDomain.BaseDirectory, "*.dll"))
        {
            Assembly.LoadFrom(dll);
        }
        var connected = new System.Threading.ManualResetEvent(false);
        IProtocol protocol = ProtocolInitializer.GetProtocol(Protocol.WebSocketSharp, args[0]);
        protocol.OnConnected += (sender, e) => connected.Set();
        var socket = new RosSocket(protocol, RosSocket.SerializerEnum.Newtonsoft_JSON);
        if (!connected.WaitOne(10000))
        {
            Console.Error.WriteLine("no connection to " + args[0]);
            return 1;
        }
        foreach (string line in File.ReadAllLines(args[1]).Where(l => l.Length > 0))
        {
            string[] parts = line.Split(' ');
            Type relay = typeof(Relay<>).MakeGenericType(FindType(parts[2]));
            relay.GetMethod("Start").Invoke(null, new object[] { socket, parts[0], parts[1] });
        }
        Console.WriteLine("ready");
        Console.Out.Flush();
        Console.In.ReadToEnd();
        socket.Close();
        return 0;
    }
}

public static class Relay<T> where T : Message
{
    public static void Start(RosSocket socket, string input, string output)
    {
        string publication = socket.Advertise<T>(output);
        socket.Subscribe<T>(input, message => socket.Publish(publication, message));
    }
}

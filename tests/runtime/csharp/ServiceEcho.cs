// Test program: both halves of every planned service through ROS#'s real client, both ways.
// Usage: mono ServiceEcho.exe WS_URL PLAN_FILE; each line "PY_SERVICE CS_SERVICE ReqClass RespClass".
// Per line: call PY_SERVICE (a rospy server) and keep the response it returns (deserialized
// by ROS#); then advertise CS_SERVICE, which answers every call with that kept response
// (serialized by ROS#) and passes the request it received on to PY_SERVICE unchanged.
// Prints "ready" once every CS_SERVICE is advertised; exits when stdin closes.
using System;
using System.IO;
using System.Linq;
using System.Reflection;
using System.Threading;
using RosSharp.RosBridgeClient;
using RosSharp.RosBridgeClient.Protocols;

public static class ServiceEcho
{
    public static int Main(string[] args)
    {
        foreach (string dll in Directory.GetFiles(AppDomain.CurrentDomain.BaseDirectory, "*.dll"))
        {
            Assembly.LoadFrom(dll);
        }
        var connected = new ManualResetEvent(false);
        IProtocol protocol = ProtocolInitializer.GetProtocol(Protocol.WebSocketSharp, args[0]);
        protocol.OnConnected += (sender, e) => connected.Set();
        var socket = new RosSocket(protocol, RosSocket.SerializerEnum.Newtonsoft_JSON);
        if (!connected.WaitOne(10000))
        {
            Console.Error.WriteLine("no connection to " + args[0]);
            return 1;
        }
        string[] lines = File.ReadAllLines(args[1]).Where(l => l.Length > 0).ToArray();
        var advertised = new CountdownEvent(lines.Length);
        foreach (string line in lines)
        {
            string[] parts = line.Split(' ');
            Type relay = typeof(ServiceRelay<,>).MakeGenericType(Echo.FindType(parts[2]), Echo.FindType(parts[3]));
            relay.GetMethod("Start").Invoke(null, new object[] { socket, parts[0], parts[1], advertised });
        }
        if (!advertised.Wait(60000))
        {
            Console.Error.WriteLine("not every rospy service answered");
            return 1;
        }
        Console.WriteLine("ready");
        Console.Out.Flush();
        Console.In.ReadToEnd();
        return 0;
    }
}

public static class ServiceRelay<TRequest, TResponse> where TRequest : Message, new() where TResponse : Message
{
    public static void Start(RosSocket socket, string python, string ours, CountdownEvent advertised)
    {
        socket.CallService<TRequest, TResponse>(python, kept =>
        {
            socket.AdvertiseService<TRequest, TResponse>(ours, (TRequest request, out TResponse response) =>
            {
                response = kept;
                // Not from the socket thread: ROS# delivers the answer on it.
                ThreadPool.QueueUserWorkItem(_ => socket.CallService<TRequest, TResponse>(python, ignored => { }, request));
                return true;
            });
            advertised.Signal();
        }, new TRequest());
    }
}

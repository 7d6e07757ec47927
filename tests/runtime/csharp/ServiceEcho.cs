// Test program: both halves of every planned service through ROS#'s real client, both ways.
// Usage: mono ServiceEcho.exe WS_URL PLAN_FILE; each line "PY_SERVICE CS_SERVICE ReqClass RespClass".
// Line after line: call PY_SERVICE (a rospy server) and keep the response it returns (deserialized
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
        var advertised = new ManualResetEvent(false);
        string current = null;
        // One service after the other, each next call made from the previous one's response
        // handler: RosSocket's dictionaries are not thread-safe, so every use of the socket after
        // the first call happens on the thread that delivers its messages.
        Action next = () => advertised.Set();
        foreach (string line in lines.Reverse())
        {
            string[] parts = line.Split(' ');
            Type relay = typeof(ServiceRelay<,>).MakeGenericType(Echo.FindType(parts[2]), Echo.FindType(parts[3]));
            Action then = next;
            next = () =>
            {
                Volatile.Write(ref current, parts[0]);
                relay.GetMethod("Start").Invoke(null, new object[] { socket, parts[0], parts[1], then });
            };
        }
        next();
        if (!advertised.WaitOne(60000))
        {
            // ROS# 2.2.1 throws on rosbridge's failure reply (a text where it expects the
            // response's JSON) and never calls the handler.
            Console.Error.WriteLine("no response from " + Volatile.Read(ref current));
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
    public static void Start(RosSocket socket, string python, string ours, Action then)
    {
        socket.CallService<TRequest, TResponse>(python, kept =>
        {
            socket.AdvertiseService<TRequest, TResponse>(ours, (TRequest request, out TResponse response) =>
            {
                response = kept;
                socket.CallService<TRequest, TResponse>(python, ignored => { }, request);
                return true;
            });
            then();
        }, new TRequest());
    }
}

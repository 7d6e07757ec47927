// Test program: generated scripts meeting the failures a Unity user meets first, in the
// UnityEngine stand-in's frame loop (UnityEngineRuntime.cs) with ROS#'s real RosConnector:
// rosbridge not running, a wrong port (something else answers there), and, with a working
// rosbridge, a type it cannot load (ghost_msgs, unknown to it) and a service nobody serves.
// The scripts come from a small generated project (test_failures.py). Each log line is printed;
// "done" means no exception ended the frame loop.
// Usage: mono FailureScenario.exe WS_URL WRONG_PORT_URL NOT_RUNNING_URL
using System;
using System.Threading;
using RosGenerated;
using RosSharp.RosBridgeClient;
using RosSharp.RosBridgeClient.Protocols;
using UnityEngine;
using Ghost = RosSharp.RosBridgeClient.MessageTypes.Ghost;
using Std = RosSharp.RosBridgeClient.MessageTypes.Std;

public static class FailureScenario
{
    static void Frames(float seconds)
    {
        float end = Time.realtimeSinceStartup + seconds;
        while (Time.realtimeSinceStartup < end)
        {
            Player.Frame();
            Thread.Sleep(16);
        }
    }

    static RosConnector Connector(string name, string url, int timeout)
    {
        return new GameObject(name).AddComponent<RosConnector>(c =>
        {
            c.RosBridgeServerUrl = url;
            c.SecondsTimeout = timeout;
            c.Serializer = RosSocket.SerializerEnum.Newtonsoft_JSON;
            c.protocol = Protocol.WebSocketSharp;
            c.selectedRosVersion = RosVersion.ROS1;
        });
    }

    public static int Main(string[] args)
    {
        var working = Connector("Working", args[0], 2);
        var wrongPort = Connector("WrongPort", args[1], 1);
        var notRunning = Connector("NotRunning", args[2], 1);
        new GameObject("Wrong").AddComponent<GhostSubscriber>(s => s.Connector = wrongPort);
        var wrongClient = new GameObject("WrongClient").AddComponent<NobodyClient>(s => s.Connector = wrongPort);
        new GameObject("Absent").AddComponent<GhostSubscriber>(s => s.Connector = notRunning);
        float giveUp = Time.realtimeSinceStartup + 30;
        while (!working.IsConnected.WaitOne(0) && Time.realtimeSinceStartup < giveUp)
        {
            Frames(0.1f);
        }
        // Added once connected, so that the short SecondsTimeout (the subscriber's silence
        // hint) is not spent on connecting, which can take seconds on a loaded machine.
        var robot = new GameObject("Robot");
        robot.AddComponent<GhostSubscriber>(s => s.Connector = working);
        robot.AddComponent<GhostOutPublisher>(s => s.Connector = working);
        var haunt = robot.AddComponent<HauntClient>(s => { s.Connector = working; s.ResponseTimeout = 2; });
        var nobody = robot.AddComponent<NobodyClient>(s => { s.Connector = working; s.ResponseTimeout = 2; });
        haunt.Call(new Ghost.HauntRequest());
        nobody.Call(new Std.TriggerRequest());
        wrongClient.Call(new Std.TriggerRequest());
        Frames(4f);
        Console.WriteLine("done");
        Console.Out.Flush();
        working.RosSocket.Close();
        return 0;
    }
}

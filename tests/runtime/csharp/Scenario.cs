// Test program: the sample project's generated scripts in the UnityEngine stand-in's frame loop
// (UnityEngineRuntime.cs), with ROS#'s real RosConnector and client, against a real rosbridge.
// The user halves below record what the generated halves hand them. Prints "key value" lines.
// Usage: mono Scenario.exe WS_URL UNREACHABLE_WS_URL
using System;
using System.Collections.Generic;
using System.Linq;
using System.Threading;
using RosGenerated;
using RosSharp.RosBridgeClient;
using RosSharp.RosBridgeClient.Protocols;
using UnityEngine;
using Geometry = RosSharp.RosBridgeClient.MessageTypes.Geometry;
using Nav = RosSharp.RosBridgeClient.MessageTypes.Nav;
using Sensor = RosSharp.RosBridgeClient.MessageTypes.Sensor;
using Diffbot = RosSharp.RosBridgeClient.MessageTypes.Diffbot;

namespace RosGenerated
{
    public partial class CmdVelPublisher
    {
        public int Updates;
        partial void UpdateMessage(Geometry.Twist message) { message.linear.x = ++Updates; }
    }

    public partial class OdomSubscriber
    {
        public int Count;
        partial void OnMessage(Nav.Odometry message) { Scenario.OnMain("odom"); Count++; }
    }

    public partial class BaseStatusSubscriber
    {
        public readonly List<string> Order = new List<string>();
        partial void OnMessage(Diffbot.BaseStatus message) { Scenario.OnMain("base_status"); Order.Add(message.header.frame_id); }
    }

    public partial class ScanSubscriber
    {
        public int Count, ThisFrame, MostInOneFrame;
        partial void OnMessage(Sensor.LaserScan message)
        {
            Scenario.OnMain("scan");
            Count++;
            ThisFrame++;
            MostInOneFrame = Math.Max(MostInOneFrame, ThisFrame);
        }
    }
}

public static class Scenario
{
    static int mainThread;
    static int offMain;

    public static void OnMain(string what)
    {
        if (Thread.CurrentThread.ManagedThreadId != mainThread) Interlocked.Increment(ref offMain);
    }

    static void Report(string key, object value)
    {
        Console.WriteLine(key + " " + value);
        Console.Out.Flush();
    }

    static void Frames(float seconds, Action each = null)
    {
        float end = Time.realtimeSinceStartup + seconds;
        while (Time.realtimeSinceStartup < end)
        {
            Player.Frame();
            if (each != null) each();
            Thread.Sleep(16);
        }
    }

    public static int Main(string[] args)
    {
        mainThread = Thread.CurrentThread.ManagedThreadId;
        Action<RosConnector> settings = c =>
        {
            c.RosBridgeServerUrl = args[0];
            c.Serializer = RosSocket.SerializerEnum.Newtonsoft_JSON;
            c.protocol = Protocol.WebSocketSharp;
#if ROS2
            c.selectedRosVersion = RosVersion.ROS2;
#else
            c.selectedRosVersion = RosVersion.ROS1;
#endif
        };
        // The scripts start in the same frame as the connector, before its thread has connected.
        var connector = new GameObject("RosConnector").AddComponent<RosConnector>(settings);
        var robot = new GameObject("Robot");
        var publisher = robot.AddComponent<CmdVelPublisher>();
        var odom = robot.AddComponent<OdomSubscriber>();
        var status = robot.AddComponent<BaseStatusSubscriber>();
        var scan = new GameObject("Lidar").AddComponent<ScanSubscriber>();
        int connectedFrame = -1;
        Action each = () =>
        {
            scan.ThisFrame = 0;
            if (connectedFrame < 0 && connector.IsConnected.WaitOne(0)) connectedFrame = Player.FrameCount;
        };
        // The 4 s window starts once connected: on a loaded machine connecting can take seconds.
        float giveUp = Time.realtimeSinceStartup + 30;
        while (connectedFrame < 0 && Time.realtimeSinceStartup < giveUp) Frames(0.05f, each);
        Frames(4f, each);
        Report("connected_frame", connectedFrame);
        Report("updates", publisher.Updates);
        Report("odom", odom.Count);
        Report("base_status", string.Join(",", status.Order));
        Report("scan", scan.Count);
        Report("scan_most_in_one_frame", scan.MostInOneFrame);
        Report("queue", scan.Queue);
        Report("throttle", scan.Throttle);
        Report("off_main_thread", offMain);
        UnityEngine.Object.Destroy(odom);
        Report("destroyed", "odom");
        Frames(0.5f);
        Report("waiting", "check");
        Console.In.ReadLine();  // the test checks rosbridge's subscriptions meanwhile

        // A connector that never connects: the script gives up after SecondsTimeout, logs once.
        var lost = new GameObject("Lost").AddComponent<RosConnector>(c =>
        {
            settings(c);
            c.RosBridgeServerUrl = args[1];
            c.SecondsTimeout = 1;
        });
        new GameObject("LostRobot").AddComponent<BaseStatusSubscriber>(s => s.Connector = lost);
        Frames(2f);
        Report("done", Player.FrameCount);
        connector.RosSocket.Close();
        return 0;
    }
}

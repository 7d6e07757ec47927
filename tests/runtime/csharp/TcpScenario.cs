// Test program: generated ROS-TCP-Connector scripts in the UnityEngine stand-in's frame loop
// (UnityEngineRuntime.cs), with the connector's real ROSConnection, against a real
// ROS-TCP-Endpoint and rospy node (with rospy's actionlib). The user halves below record what the generated halves hand
// them. Prints "key value" lines. Usage: mono TcpScenario.exe HOST PORT
using System;
using System.Collections.Generic;
using System.Threading;
using RosGenerated;
using RosMessageTypes.Nav;
using RosMessageTypes.Std;
using Unity.Robotics.ROSTCPConnector;
using UnityEngine;

namespace RosGenerated
{
    public partial class ChatterPublisher
    {
        public int Updates;
        partial void UpdateMessage(StringMsg message) { message.data = "hello " + (++Updates); }
    }

    public partial class EchoSubscriber
    {
        public readonly List<string> Got = new List<string>();
        partial void OnMessage(StringMsg message) { TcpScenario.OnMain(); Got.Add(message.data); }
    }

    public partial class TriggerClient
    {
        public string Answer;
        partial void OnResponse(TriggerResponse response)
        {
            TcpScenario.OnMain();
            Answer = response.success + " " + response.message;
        }
    }

    public partial class SetServer
    {
        public int Calls;
        partial void HandleRequest(SetBoolRequest request, SetBoolResponse response, ref bool success)
        {
            TcpScenario.OnMain();
            Calls++;
            response.success = request.data;
            response.message = "set to " + request.data;
        }
    }
}

namespace RosGenerated
{
    public partial class MapActionClient
    {
        public string Result;
        partial void OnFeedback(string goalId, GetMapFeedback feedback) { TcpScenario.OnMain(); }
        partial void OnResult(string goalId, byte status, GetMapResult result)
        {
            TcpScenario.OnMain();
            Result = status + " " + result.map.header.frame_id + " " + result.map.info.width;
        }
    }

    public partial class SimMapActionServer
    {
        public int Goals;
        partial void OnGoal(string goalId, GetMapGoal goal, ref bool accept)
        {
            TcpScenario.OnMain();
            Goals++;
            var result = new GetMapResult();
            result.map.header.frame_id = "map-from-unity";
            SetSucceeded(goalId, result);
        }

        partial void OnCancel(string goalId) { }
    }
}

public static class TcpScenario
{
    static int mainThread;
    static int offMain;

    public static void OnMain()
    {
        if (Thread.CurrentThread.ManagedThreadId != mainThread) Interlocked.Increment(ref offMain);
    }

    public static int Main(string[] args)
    {
        mainThread = Thread.CurrentThread.ManagedThreadId;
        Player.Boot();
        new GameObject("ROSConnection").AddComponent<ROSConnection>(c =>
        {
            c.RosIPAddress = args[0];
            c.RosPort = int.Parse(args[1]);
            c.ShowHud = false;
            c.listenForTFMessages = false;
        });
        var robot = new GameObject("Robot");
        robot.AddComponent<ChatterPublisher>();
        var echo = robot.AddComponent<EchoSubscriber>();
        var trigger = robot.AddComponent<TriggerClient>();
        var set = robot.AddComponent<SetServer>();
        var mapClient = robot.AddComponent<MapActionClient>();
        var mapServer = robot.AddComponent<SimMapActionServer>();
        bool goalSent = false;
        float doneAt = -1f;
        float nextCall = 1f;
        float deadline = Time.realtimeSinceStartup + 40f;
        while (Time.realtimeSinceStartup < deadline)
        {
            Player.Frame();
            if (trigger.Answer == null && Time.realtimeSinceStartup > nextCall)
            {
                trigger.Call(new TriggerRequest());
                nextCall = Time.realtimeSinceStartup + 3f;
            }
            if (!goalSent && Time.realtimeSinceStartup > 1f)
            {
                goalSent = mapClient.SendGoal(new GetMapGoal()) != null;
            }
            bool done = echo.Got.Count > 0 && trigger.Answer != null && set.Calls > 0
                && mapClient.Result != null && mapServer.Goals > 0;
            if (done && doneAt < 0f) doneAt = Time.realtimeSinceStartup;
            // a few more seconds of frames: the rospy client's result is still on its way
            if (doneAt >= 0f && Time.realtimeSinceStartup > doneAt + 3f) break;
            Thread.Sleep(10);
        }
        Console.WriteLine("echo " + (echo.Got.Count > 0 ? echo.Got[0] : "none"));
        Console.WriteLine("trigger " + (trigger.Answer ?? "none"));
        Console.WriteLine("set_calls " + set.Calls);
        Console.WriteLine("map_result " + (mapClient.Result ?? "none"));
        Console.WriteLine("map_goals " + mapServer.Goals);
        Console.WriteLine("off_main " + offMain);
        Console.Out.Flush();
        Environment.Exit(0);  // the connector's socket thread is no background thread
        return 0;
    }
}

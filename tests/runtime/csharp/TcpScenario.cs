// Test program: generated ROS-TCP-Connector scripts in the UnityEngine stand-in's frame loop
// (UnityEngineRuntime.cs), with the connector's real ROSConnection, against a real
// ROS-TCP-Endpoint and rospy node. The user halves below record what the generated halves hand
// them. Prints "key value" lines. Usage: mono TcpScenario.exe HOST PORT
using System;
using System.Collections.Generic;
using System.Threading;
using RosGenerated;
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
            if (echo.Got.Count > 0 && trigger.Answer != null && set.Calls > 0) break;
            Thread.Sleep(10);
        }
        Console.WriteLine("echo " + (echo.Got.Count > 0 ? echo.Got[0] : "none"));
        Console.WriteLine("trigger " + (trigger.Answer ?? "none"));
        Console.WriteLine("set_calls " + set.Calls);
        Console.WriteLine("off_main " + offMain);
        Console.Out.Flush();
        Environment.Exit(0);  // the connector's socket thread is no background thread
        return 0;
    }
}

// Test program: the service scripts unityscaffold generates for
//   services: [{name: /set_speed_limit, role: client}, {name: /reset_cs, role: server}]
// (diffbot_msgs/srv/SetSpeedLimit and std_srvs/srv/Trigger, on GameObject Robot), run in the
// UnityEngine stand-in's frame loop (UnityEngineRuntime.cs) with ROS#'s real RosConnector and
// client (built for ROS 2). The user halves below:
// - client: once connected, calls with max_linear 1.25, then, on its response, with 9.5;
//   reports each response (on the frame loop's thread);
// - server: answers every request with success true and "reset <n>" (on ROS#'s socket thread).
// Prints one "key value" line per event; when stdin closes, destroys both scripts and exits.
// Usage: mono ServiceScenario.exe WS_URL
using System;
using System.Threading;
using RosGenerated;
using RosSharp.RosBridgeClient;
using RosSharp.RosBridgeClient.MessageTypes.Diffbot;
using RosSharp.RosBridgeClient.MessageTypes.Std;
using RosSharp.RosBridgeClient.Protocols;
using UnityEngine;

namespace RosGenerated
{
    public partial class SetSpeedLimitClient
    {
        partial void OnResponse(SetSpeedLimitResponse response)
        {
            ServiceScenario.OnMain();
            ServiceScenario.Report("client_response", response.success + " " + response.message);
            if (response.message.StartsWith("limit 1.25")) Call(new SetSpeedLimitRequest(9.5f));
        }
    }

    public partial class ResetCsServer
    {
        int served;

        partial void HandleRequest(TriggerRequest request, TriggerResponse response, ref bool success)
        {
            served++;
            response.success = true;
            response.message = "reset " + served;
            ServiceScenario.Report("server_request", served);
        }
    }
}

public static class ServiceScenario
{
    static int mainThread;
    static int offMain;

    public static void OnMain()
    {
        if (Thread.CurrentThread.ManagedThreadId != mainThread) Interlocked.Increment(ref offMain);
    }

    public static void Report(string key, object value)
    {
        Console.WriteLine(key + " " + value);
        Console.Out.Flush();
    }

    public static int Main(string[] args)
    {
        mainThread = Thread.CurrentThread.ManagedThreadId;
        var connector = new GameObject("RosConnector").AddComponent<RosConnector>(c =>
        {
            c.RosBridgeServerUrl = args[0];
            c.Serializer = RosSocket.SerializerEnum.Newtonsoft_JSON;
            c.protocol = Protocol.WebSocketSharp;
            c.selectedRosVersion = RosVersion.ROS2;
        });
        var robot = new GameObject("Robot");
        var client = robot.AddComponent<SetSpeedLimitClient>();
        var server = robot.AddComponent<ResetCsServer>();
        var ended = new ManualResetEvent(false);
        new Thread(() => { Console.In.ReadToEnd(); ended.Set(); }) { IsBackground = true }.Start();
        bool sent = false;
        float giveUp = Time.realtimeSinceStartup + 300;
        while (!ended.WaitOne(0) && Time.realtimeSinceStartup < giveUp)
        {
            Player.Frame();
            if (!sent && connector.IsConnected.WaitOne(0))
            {
                sent = true;
                client.Call(new SetSpeedLimitRequest(1.25f));
            }
            Thread.Sleep(16);
        }
        UnityEngine.Object.Destroy(server);
        UnityEngine.Object.Destroy(client);
        Player.Frame();
        Report("off_main_thread", offMain);
        Report("destroyed", Player.FrameCount);
        connector.RosSocket.Close();
        return 0;
    }
}

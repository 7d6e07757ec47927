// Test program: the action scripts unityscaffold generates for
//   actions: [{name: /dock_py, role: client}, {name: /dock_cs, role: server}]
// (diffbot_msgs/action/Dock, on GameObject Robot), run in the UnityEngine stand-in's frame loop
// (UnityEngineRuntime.cs) with ROS#'s real RosConnector and client. The user halves below do
// what data/action_node.py's side expects (and data/ros2/action_node.py's, for ROS 2):
// - client: goal "alpha" once connected; when its result comes, goal "cancel-me", cancelled at
//   its first feedback; with ROS 2 then goal "reject-me", which the other side refuses;
//   with ROS 1 also, at once, goal "late" from a second client (/dock_late, DockLateActionClient);
// - server: every goal gets one feedback (3.5 m); "cancel-me" runs until cancelled (then
//   SetCanceled: docked false, battery -1), any other goal SetSucceeded (docked, 42.25 %).
// Compiled with -define:ROS2 for ROS 2. Prints one "key value" line per event; when stdin
// closes, destroys both scripts (OnDestroy), runs a few frames and exits.
// Usage: mono ActionScenario.exe WS_URL
using System;
using System.Collections.Generic;
using System.Threading;
using RosGenerated;
using RosSharp.RosBridgeClient;
using RosSharp.RosBridgeClient.MessageTypes.Diffbot;
using RosSharp.RosBridgeClient.Protocols;
using UnityEngine;
#if ROS2
using Status = System.SByte;
#else
using Status = System.Byte;
#endif

namespace RosGenerated
{
    public partial class DockPyActionClient
    {
        public readonly Dictionary<string, string> Goals = new Dictionary<string, string>();
        bool cancelSent;

        public void Send(string dockId)
        {
            string goalId = SendGoal(new DockGoal(dockId));
            Goals[goalId ?? "null"] = dockId;
            ActionScenario.Report("client_sent", dockId + " " + goalId);
        }

        partial void OnFeedback(string goalId, DockFeedback feedback)
        {
            ActionScenario.OnMain();
            string dockId = Goals[goalId];
            ActionScenario.Report("client_feedback", dockId + " " + feedback.distance_remaining.ToString("R"));
            if (dockId == "cancel-me" && !cancelSent)
            {
                cancelSent = true;
                CancelGoal(goalId);
                ActionScenario.Report("client_cancel", dockId);
            }
        }

        partial void OnResult(string goalId, Status status, DockResult result)
        {
            ActionScenario.OnMain();
            string dockId = Goals[goalId];
            ActionScenario.Report("client_result", dockId + " " + status + " " + result.docked + " " + result.battery.ToString("R"));
            if (dockId == "alpha") Send("cancel-me");
#if ROS2
            else if (dockId == "cancel-me") Send("reject-me");
#endif
        }
    }

#if !ROS2
    // A goal to data/late_action_server.py, which subscribes to its goals only after the
    // client's first publication of it was lost.
    public partial class DockLateActionClient
    {
        partial void OnResult(string goalId, Status status, DockResult result)
        {
            ActionScenario.OnMain();
            ActionScenario.Report("late_result", goalId + " " + status + " " + result.docked + " " + result.battery.ToString("R"));
        }
    }

#endif
    public partial class DockCsActionServer
    {
        partial void OnGoal(string goalId, DockGoal goal, ref bool accept)
        {
            ActionScenario.OnMain();
            ActionScenario.Report("server_goal", goal.dock_id + " " + goalId);
            PublishFeedback(goalId, new DockFeedback(3.5f));
            if (goal.dock_id != "cancel-me") SetSucceeded(goalId, new DockResult(true, 42.25f));
        }

        partial void OnCancel(string goalId)
        {
            ActionScenario.OnMain();
            ActionScenario.Report("server_cancel", goalId);
            SetCanceled(goalId, new DockResult(false, -1f));
        }
    }
}

public static class ActionScenario
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
#if ROS2
            c.selectedRosVersion = RosVersion.ROS2;
#else
            c.selectedRosVersion = RosVersion.ROS1;
#endif
        });
        var robot = new GameObject("Robot");
        var client = robot.AddComponent<DockPyActionClient>();
        var server = robot.AddComponent<DockCsActionServer>();
#if ROS2
        // "reject-me" never gets an answer ROS# can read: warn soon instead of after 10 s.
        client.ResponseTimeout = 1f;
#endif
#if !ROS2
        var late = robot.AddComponent<DockLateActionClient>();
#endif
        var ended = new ManualResetEvent(false);
        new Thread(() => { Console.In.ReadToEnd(); ended.Set(); }) { IsBackground = true }.Start();
        bool sent = false;
        // Frames until stdin closes (a guard of 5 minutes against a hang).
        float giveUp = Time.realtimeSinceStartup + 300;
        while (!ended.WaitOne(0) && Time.realtimeSinceStartup < giveUp)
        {
            Player.Frame();
            if (!sent && connector.IsConnected.WaitOne(0))
            {
                sent = true;
                client.Send("alpha");
#if !ROS2
                Report("late_sent", late.SendGoal(new DockGoal("late")));
#endif
            }
            Thread.Sleep(16);
        }
        UnityEngine.Object.Destroy(server);
        UnityEngine.Object.Destroy(client);
#if !ROS2
        UnityEngine.Object.Destroy(late);
#endif
        Player.Frame();
        Report("off_main_thread", offMain);
        Report("destroyed", Player.FrameCount);
        connector.RosSocket.Close();
        return 0;
    }
}

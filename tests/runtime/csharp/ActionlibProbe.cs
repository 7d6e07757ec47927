// Test program: actionlib's protocol (ROS 1) spoken with ROS#'s real RosSocket and the classes
// unityscaffold generates for diffbot_msgs/Dock, through a real rosbridge, against rospy's
// SimpleActionServer and SimpleActionClient (data/action_node.py). Both roles at once:
// - client of PY_ACTION: goal "alpha" (runs to success), then goal "cancel-me", cancelled once
//   its first feedback arrives;
// - server of CS_ACTION: "cancel-me" runs until cancelled (then PREEMPTED), any other goal
//   gets one feedback and SUCCEEDED; its status array goes out 5 times a second, as actionlib's.
// Every socket call happens on the main thread: subscription handlers only queue what arrives
// (RosSocket's dictionaries are not thread-safe; the generated scripts do the same).
// Prints one "key value" line per event; exits when stdin closes.
// Usage: mono ActionlibProbe.exe WS_URL PY_ACTION CS_ACTION
using System;
using System.Collections.Concurrent;
using System.Collections.Generic;
using System.Linq;
using System.Threading;
using RosSharp.RosBridgeClient;
using RosSharp.RosBridgeClient.MessageTypes.Actionlib;
using RosSharp.RosBridgeClient.MessageTypes.Diffbot;
using RosSharp.RosBridgeClient.MessageTypes.Std;
using RosSharp.RosBridgeClient.Protocols;

public static class ActionlibProbe
{
    static readonly BlockingCollection<Action> inbox = new BlockingCollection<Action>();
    static RosSocket socket;

    static void Report(string key, object value)
    {
        Console.WriteLine(key + " " + value);
        Console.Out.Flush();
    }

    static Time Now()
    {
        double seconds = (DateTime.UtcNow - new DateTime(1970, 1, 1, 0, 0, 0, DateTimeKind.Utc)).TotalSeconds;
        return new Time((uint)seconds, (uint)((seconds % 1) * 1e9));
    }

    static string Statuses(GoalStatusArray array)
    {
        return string.Join(",", array.status_list.Select(s => s.goal_id.id + ":" + s.status));
    }

    public static int Main(string[] args)
    {
        var connected = new ManualResetEvent(false);
        IProtocol protocol = ProtocolInitializer.GetProtocol(Protocol.WebSocketSharp, args[0]);
        protocol.OnConnected += (sender, e) => connected.Set();
        socket = new RosSocket(protocol, RosSocket.SerializerEnum.Newtonsoft_JSON);
        if (!connected.WaitOne(10000))
        {
            Console.Error.WriteLine("no connection to " + args[0]);
            return 1;
        }
        var client = new Client(args[1]);
        var server = new Server(args[2]);
        new Thread(() => { Console.In.ReadToEnd(); inbox.CompleteAdding(); }) { IsBackground = true }.Start();
        Report("ready", "");
        // The main loop: queued arrivals in order, and the server's status 5 times a second.
        DateTime nextStatus = DateTime.UtcNow;
        while (!inbox.IsCompleted)
        {
            Action work;
            if (inbox.TryTake(out work, 50)) work();
            if (DateTime.UtcNow >= nextStatus)
            {
                server.PublishStatus();
                nextStatus = DateTime.UtcNow.AddMilliseconds(200);
            }
        }
        socket.Close();
        return 0;
    }

    static void Queue(Action work)
    {
        try { inbox.Add(work); } catch (InvalidOperationException) { }  // stdin closed: ending
    }

    sealed class Client
    {
        readonly string goalTopic, cancelTopic;
        readonly HashSet<string> seen = new HashSet<string>();
        int resends;
        string current;

        public Client(string action)
        {
            goalTopic = socket.Advertise<DockActionGoal>(action + "/goal");
            cancelTopic = socket.Advertise<GoalID>(action + "/cancel");
            socket.Subscribe<GoalStatusArray>(action + "/status", s => Queue(() => OnStatus(s)));
            // queue_length 0: rosbridge passes on every message. ROS#'s default (1) lets
            // rosbridge drop all but the newest of a burst: the first of two feedbacks sent
            // back to back was lost that way, and so could a result be.
            socket.Subscribe<DockActionFeedback>(action + "/feedback", f => Queue(() => OnFeedback(f)), queue_length: 0);
            socket.Subscribe<DockActionResult>(action + "/result", r => Queue(() => OnResult(r)), queue_length: 0);
        }

        void Send(string id, string dockId)
        {
            current = id;
            var goal = new DockActionGoal(new Header(0, Now(), ""), new GoalID(Now(), id), new DockGoal(dockId));
            socket.Publish(goalTopic, goal);
            Report("client_sent", id + " " + dockId);
        }

        // The first status from the server starts the first goal. A goal sent before rospy's
        // subscriber connected to rosbridge's new publisher is lost (rosbridge replays what
        // was published in the first second after advertising only), so a goal the server's
        // status does not list yet is sent again (the server ignores a goal id it knows).
        void OnStatus(GoalStatusArray status)
        {
            string line = Statuses(status);
            if (seen.Add(line)) Report("client_status", line);
            if (current == null) Send("cs-goal-1", "alpha");
            else if (!status.status_list.Any(s => s.goal_id.id == current) && resends++ < 20)
            {
                socket.Publish(goalTopic, new DockActionGoal(new Header(0, Now(), ""), new GoalID(Now(), current), new DockGoal(current == "cs-goal-1" ? "alpha" : "cancel-me")));
            }
        }

        void OnFeedback(DockActionFeedback feedback)
        {
            Report("client_feedback", feedback.status.goal_id.id + " " + feedback.status.status + " " + feedback.feedback.distance_remaining.ToString("R"));
            if (feedback.status.goal_id.id == "cs-goal-2")
            {
                // Cancel this goal only: its id, and a zero stamp (a stamp would also cancel
                // every goal sent before it).
                socket.Publish(cancelTopic, new GoalID(new Time(), "cs-goal-2"));
                Report("client_cancel", "cs-goal-2");
            }
        }

        void OnResult(DockActionResult result)
        {
            Report("client_result", result.status.goal_id.id + " " + result.status.status + " " + result.result.docked + " " + result.result.battery.ToString("R") + " " + result.status.text);
            if (result.status.goal_id.id == "cs-goal-1") Send("cs-goal-2", "cancel-me");
        }
    }

    sealed class Server
    {
        readonly string statusTopic, feedbackTopic, resultTopic;
        readonly Dictionary<string, GoalStatus> goals = new Dictionary<string, GoalStatus>();

        public Server(string action)
        {
            statusTopic = socket.Advertise<GoalStatusArray>(action + "/status");
            feedbackTopic = socket.Advertise<DockActionFeedback>(action + "/feedback");
            resultTopic = socket.Advertise<DockActionResult>(action + "/result");
            socket.Subscribe<DockActionGoal>(action + "/goal", g => Queue(() => OnGoal(g)), queue_length: 0);
            socket.Subscribe<GoalID>(action + "/cancel", c => Queue(() => OnCancel(c)), queue_length: 0);
        }

        public void PublishStatus()
        {
            socket.Publish(statusTopic, new GoalStatusArray(new Header(0, Now(), ""), goals.Values.ToArray()));
        }

        void OnGoal(DockActionGoal goal)
        {
            string id = goal.goal_id.id;
            Report("server_goal", id + " " + goal.goal_id.stamp.secs + " " + goal.goal.dock_id);
            if (goals.ContainsKey(id)) return;
            var status = new GoalStatus(goal.goal_id, GoalStatus.ACTIVE, "");
            goals[id] = status;
            PublishStatus();
            socket.Publish(feedbackTopic, new DockActionFeedback(new Header(0, Now(), ""), status, new DockFeedback(3.5f)));
            if (goal.goal.dock_id != "cancel-me")
            {
                Finish(status, GoalStatus.SUCCEEDED, "docked at " + goal.goal.dock_id, new DockResult(true, 42.25f));
            }
        }

        void OnCancel(GoalID cancel)
        {
            Report("server_cancel", cancel.id + " " + cancel.stamp.secs);
            GoalStatus status;
            if (goals.TryGetValue(cancel.id, out status) && status.status == GoalStatus.ACTIVE)
            {
                status.status = GoalStatus.PREEMPTING;
                PublishStatus();
                Finish(status, GoalStatus.PREEMPTED, "cancelled", new DockResult(false, -1f));
            }
        }

        void Finish(GoalStatus status, byte state, string text, DockResult result)
        {
            status.status = state;
            status.text = text;
            socket.Publish(resultTopic, new DockActionResult(new Header(0, Now(), ""), status, result));
            PublishStatus();
        }
    }
}

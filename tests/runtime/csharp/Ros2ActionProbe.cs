// Test program: ROS 2 actions through ROS#'s real RosSocket action API (ROS# built with
// -define:ROS2) with the classes unityscaffold generates for diffbot_msgs/action/Dock, against
// the real rosbridge 2.x and rclpy (data/ros2/action_node.py). Both roles at once:
// - client of CLIENT_ACTION: goal "alpha" (runs to success), then "cancel-me", cancelled once
//   its first feedback arrives, then "reject-me" (the server refuses it);
// - server of SERVER_ACTION: "cancel-me" runs until cancelled (then CANCELED), any other goal
//   gets one feedback and SUCCEEDED. Unadvertised when stdin closes.
// Socket calls happen on the main thread; handlers only queue what arrives.
// Prints one "key value" line per event.
// Usage: mono Ros2ActionProbe.exe WS_URL CLIENT_ACTION SERVER_ACTION
using System;
using System.Collections.Concurrent;
using System.Threading;
using RosSharp.RosBridgeClient;
using RosSharp.RosBridgeClient.MessageTypes.Diffbot;
using RosSharp.RosBridgeClient.Protocols;

public static class Ros2ActionProbe
{
    // action_msgs/msg/GoalStatus
    const sbyte SUCCEEDED = 4, CANCELED = 5;
    static readonly BlockingCollection<Action> inbox = new BlockingCollection<Action>();
    static RosSocket socket;

    static void Report(string key, object value)
    {
        Console.WriteLine(key + " " + value);
        Console.Out.Flush();
    }

    static void Queue(Action work)
    {
        try { inbox.Add(work); } catch (InvalidOperationException) { }
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
        var server = new Server(args[2]);
        var client = new Client(args[1]);
        client.Send("alpha");
        new Thread(() => { Console.In.ReadToEnd(); inbox.CompleteAdding(); }) { IsBackground = true }.Start();
        foreach (Action work in inbox.GetConsumingEnumerable()) work();
        server.Stop();
        socket.Close();
        return 0;
    }

    sealed class Client
    {
        readonly string action;
        bool cancelled;

        public Client(string action) { this.action = action; }

        public void Send(string dockId)
        {
            var goal = new DockActionGoal();
            goal.action = action;
            goal.args = new DockGoal(dockId);
            goal.feedback = true;  // rosbridge sends action_feedback only when asked to
            // ROS# copies these two from the goal into send_action_goal; left unset they go out
            // as null and 0, and rosbridge refuses a null "compression" (not a string).
            goal.compression = "none";
            goal.fragment_size = int.MaxValue;
            string id = socket.SendActionGoalRequest<DockActionGoal, DockGoal, DockActionFeedback, DockActionResult>(
                goal, r => Queue(() => OnResult(dockId, r)), f => Queue(() => OnFeedback(dockId, f)));
            Report("client_sent", id + " " + dockId);
        }

        void OnFeedback(string dockId, DockActionFeedback feedback)
        {
            Report("client_feedback", feedback.id + " " + feedback.action + " " + feedback.values.distance_remaining.ToString("R"));
            if (dockId == "cancel-me" && !cancelled)
            {
                cancelled = true;
                socket.CancelActionGoalRequest<DockActionResult>(feedback.id, action, r => Queue(() => Report("client_cancel_response", r.id)));
                Report("client_cancel", feedback.id);
            }
        }

        void OnResult(string dockId, DockActionResult result)
        {
            Report("client_result", result.id + " " + result.action + " " + result.status + " " + result.result + " " + result.values.docked + " " + result.values.battery.ToString("R"));
            if (dockId == "alpha") Send("cancel-me");
            else if (dockId == "cancel-me") Send("reject-me");
        }
    }

    sealed class Server
    {
        readonly string action;

        public Server(string action)
        {
            this.action = action;
            socket.AdvertiseAction<DockActionGoal, DockActionFeedback, DockActionResult>(
                action, g => Queue(() => OnGoal(g)), (id, name) => Queue(() => OnCancel(id, name)));
        }

        void OnGoal(DockActionGoal goal)
        {
            Report("server_goal", goal.id + " " + goal.action + " " + goal.action_type + " " + goal.feedback + " " + goal.args.dock_id);
            var feedback = new DockActionFeedback();
            feedback.id = goal.id;
            feedback.action = action;
            feedback.values = new DockFeedback(3.5f);
            socket.RespondFeedback<DockActionFeedback, DockFeedback>(action, feedback);
            if (goal.args.dock_id != "cancel-me") Finish(goal.id, SUCCEEDED, new DockResult(true, 42.25f));
        }

        void OnCancel(string id, string name)
        {
            Report("server_cancel", id + " " + name);
            Finish(id, CANCELED, new DockResult(false, -1f));
        }

        void Finish(string id, sbyte status, DockResult values)
        {
            var result = new DockActionResult();
            result.id = id;
            result.action = action;
            result.status = status;
            result.result = true;
            result.values = values;
            socket.RespondResult<DockActionResult, DockResult>(action, result);
        }

        public void Stop()
        {
            socket.UnadvertiseAction(action);
        }
    }
}

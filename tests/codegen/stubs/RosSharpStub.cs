// A stub of the part of ROS# 2.2.1's API that generated message classes use (reference
// rossharp.md, section 8): the Message base, the ROS 1 hand-written Std.Time/Std.Duration, and
// the action bases, with the members and constructors ROS# declares. Nothing else.
// Compiled together with generated Std/Actionlib/Action classes, which the action bases use.

namespace RosSharp.RosBridgeClient
{
    public abstract class Message
    {
    }

    public abstract class Service
    {
        public abstract Message Request { get; set; }
        public abstract Message Response { get; set; }
    }

    public abstract class Action<TActionGoal, TActionResult, TActionFeedback, TGoal, TResult, TFeedback> : Message
        where TActionGoal : ActionGoal<TGoal>
        where TActionResult : ActionResult<TResult>
        where TActionFeedback : ActionFeedback<TFeedback>
        where TGoal : Message
        where TResult : Message
        where TFeedback : Message
    {
        public TActionGoal action_goal { get; set; }
        public TActionResult action_result { get; set; }
        public TActionFeedback action_feedback { get; set; }

        public Action() { }

        public Action(TActionGoal action_goal, TActionResult action_result, TActionFeedback action_feedback)
        {
            this.action_goal = action_goal;
            this.action_result = action_result;
            this.action_feedback = action_feedback;
        }
    }
}

#if !ROS2
namespace RosSharp.RosBridgeClient.MessageTypes.Std
{
    public class Time : Message
    {
        public const string RosMessageName = "std_msgs/Time";
        public uint secs { get; set; }
        public uint nsecs { get; set; }

        public Time() { }

        public Time(uint secs, uint nsecs)
        {
            this.secs = secs;
            this.nsecs = nsecs;
        }
    }

    public class Duration : Message
    {
        public const string RosMessageName = "std_msgs/Duration";
        public uint secs { get; set; }
        public uint nsecs { get; set; }

        public Duration() { }

        public Duration(uint secs, uint nsecs)
        {
            this.secs = secs;
            this.nsecs = nsecs;
        }
    }
}

namespace RosSharp.RosBridgeClient
{
    using RosSharp.RosBridgeClient.MessageTypes.Actionlib;
    using RosSharp.RosBridgeClient.MessageTypes.Std;

    public abstract class ActionGoal<TGoal> : Message where TGoal : Message
    {
        public Header header { get; set; }
        public GoalID goal_id { get; set; }
        public TGoal goal { get; set; }

        public ActionGoal()
        {
            header = new Header();
            goal_id = new GoalID();
        }

        public ActionGoal(Header header, GoalID goal_id)
        {
            this.header = header;
            this.goal_id = goal_id;
        }
    }

    public abstract class ActionResult<TResult> : Message where TResult : Message
    {
        public Header header { get; set; }
        public GoalStatus status { get; set; }
        public TResult result { get; set; }

        public ActionResult()
        {
            header = new Header();
            status = new GoalStatus();
        }

        public ActionResult(Header header, GoalStatus status)
        {
            this.header = header;
            this.status = status;
        }
    }

    public abstract class ActionFeedback<TFeedback> : Message where TFeedback : Message
    {
        public Header header { get; set; }
        public GoalStatus status { get; set; }
        public TFeedback feedback { get; set; }

        public ActionFeedback()
        {
            header = new Header();
            status = new GoalStatus();
        }

        public ActionFeedback(Header header, GoalStatus status)
        {
            this.header = header;
            this.status = status;
        }
    }
}
#else
namespace RosSharp.RosBridgeClient
{
    using RosSharp.RosBridgeClient.MessageTypes.Action;
    using RosSharp.RosBridgeClient.MessageTypes.Std;

    public abstract class ActionGoal<TGoal> : Message where TGoal : Message
    {
        public Header header { get; set; }
        public GoalInfo goalInfo { get; set; }
        public TGoal args { get; set; }
        public string id { get; set; }
        public string action { get; set; }
        public string action_type { get; set; }
        public bool feedback { get; set; }
        public int fragment_size { get; set; }
        public string compression { get; set; }

        public ActionGoal()
        {
            header = new Header();
            goalInfo = new GoalInfo();
        }

        public ActionGoal(Header header, GoalInfo goalInfo)
        {
            this.header = header;
            this.goalInfo = goalInfo;
        }
    }

    public abstract class ActionResult<TResult> : Message where TResult : Message
    {
        public Header header { get; set; }
        public string action { get; set; }
        public TResult values { get; set; }
        public sbyte status { get; set; }
        public GoalStatus goalStatus { get; set; }
        public bool result { get; set; }
        public string id { get; set; }

        public ActionResult()
        {
            header = new Header();
        }

        public ActionResult(Header header, string action, sbyte status, bool result, string id)
        {
            this.header = header;
            this.action = action;
            this.status = status;
            this.result = result;
            this.id = id;
        }
    }

    public abstract class ActionFeedback<TFeedback> : Message where TFeedback : Message
    {
        public Header header { get; set; }
        public TFeedback values { get; set; }
        public string id { get; set; }
        public string action { get; set; }

        public ActionFeedback()
        {
            header = new Header();
            id = "";
            action = "";
        }

        public ActionFeedback(Header header, string action, string id)
        {
            this.header = header;
            this.id = id;
            this.action = action;
        }
    }
}
#endif

// A compile-only stand-in for ROS# 2.2.1's runtime API (reference: rossharp.md section 8):
// RosSocket, RosConnector and the Unity base classes. Message comes from the codegen stub.
using System;
using System.Threading;
using UnityEngine;

namespace RosSharp.RosBridgeClient.Protocols
{
    public enum Protocol { WebSocketSharp, WebSocketNET }
}

namespace RosSharp.RosBridgeClient
{
    public delegate void SubscriptionHandler<T>(T t) where T : Message;
    public delegate void ServiceResponseHandler<T>(T t) where T : Message;
    public delegate bool ServiceCallHandler<Tin, Tout>(Tin tin, out Tout tout) where Tin : Message where Tout : Message;
#if ROS2
    public delegate void ActionResultResponseHandler<TActionResult>(TActionResult t) where TActionResult : Message;
    public delegate void ActionFeedbackResponseHandler<TActionFeedback>(TActionFeedback t) where TActionFeedback : Message;
    public delegate void ActionCancelResponseHandler<TActionResult>(TActionResult t) where TActionResult : Message;
    public delegate void SendActionGoalHandler<TActionGoal>(TActionGoal t) where TActionGoal : Message;
    public delegate void CancelActionGoalHandler(string frameId, string action);
#endif

    public class RosSocket
    {
        public enum SerializerEnum { Microsoft, Newtonsoft_JSON }

        public string Advertise<T>(string topic) where T : Message { return topic; }
        public void Publish(string id, Message message) { }
        public void Unadvertise(string id) { }
        public string Subscribe<T>(string topic, SubscriptionHandler<T> subscriptionHandler, int throttle_rate = 0,
            int queue_length = 1, int fragment_size = int.MaxValue, string compression = "none",
            bool ensureThreadSafety = false) where T : Message { return topic; }
        public void Unsubscribe(string id) { }
        public string AdvertiseService<Tin, Tout>(string service, ServiceCallHandler<Tin, Tout> serviceCallHandler)
            where Tin : Message where Tout : Message { return service; }
        public void UnadvertiseService(string id) { }
        public string CallService<Tin, Tout>(string service, ServiceResponseHandler<Tout> serviceResponseHandler, Tin serviceArguments)
            where Tin : Message where Tout : Message { return service; }
        public void Close(int millisecondsWait = 0) { }
#if ROS2
        public string AdvertiseAction<TActionGoal, TActionFeedback, TActionResult>(string action,
            SendActionGoalHandler<TActionGoal> sendActionGoalHandler, CancelActionGoalHandler cancelActionGoalHandler)
            where TActionGoal : Message where TActionFeedback : Message where TActionResult : Message { return action; }
        public void RespondFeedback<TActionFeedback, TFeedback>(string id, TActionFeedback actionFeedback)
            where TActionFeedback : ActionFeedback<TFeedback> where TFeedback : Message { }
        public void RespondResult<TActionResult, TResult>(string id, TActionResult ActionResult)
            where TActionResult : ActionResult<TResult> where TResult : Message { }
        public void UnadvertiseAction(string id) { }
        public string CancelActionGoalRequest<TActionResult>(string frameId, string action,
            ActionCancelResponseHandler<TActionResult> actionCancelResponseHandler) where TActionResult : Message { return action; }
        public string SendActionGoalRequest<TActionGoal, TGoal, TActionFeedback, TActionResult>(TActionGoal actionGoal,
            ActionResultResponseHandler<TActionResult> actionResultResponseHandler,
            ActionFeedbackResponseHandler<TActionFeedback> actionFeedbackResponseHandler)
            where TActionGoal : ActionGoal<TGoal> where TGoal : Message where TActionResult : Message where TActionFeedback : Message
        { return actionGoal.action; }
#endif
    }

    public enum RosVersion { ROS1 = 0, ROS2 = 1 }

    public class RosConnector : MonoBehaviour
    {
        [HideInInspector] public RosVersion selectedRosVersion = RosVersion.ROS2;
        public int SecondsTimeout = 10;
        public RosSocket.SerializerEnum Serializer;
        public Protocols.Protocol protocol;
        public string RosBridgeServerUrl = "ws://localhost:9090";
        public RosSocket RosSocket { get; private set; }
        public ManualResetEvent IsConnected { get; private set; }
        public virtual void Awake() { }
    }

    [RequireComponent(typeof(RosConnector))]
    public abstract class UnityPublisher<T> : MonoBehaviour where T : Message
    {
        public string Topic;
        protected virtual void Start() { }
        protected void Publish(T message) { }
    }

    [RequireComponent(typeof(RosConnector))]
    public abstract class UnitySubscriber<T> : MonoBehaviour where T : Message
    {
        public string Topic;
        public float TimeStep;
        public bool EnsureThreadSafety = false;
        protected virtual void Start() { }
        protected abstract void ReceiveMessage(T message);
    }

    [RequireComponent(typeof(RosConnector))]
    public abstract class UnityServiceProvider<Tin, Tout> : MonoBehaviour where Tin : Message where Tout : Message
    {
        public string ServiceName;
        protected virtual void Start() { }
        protected abstract bool ServiceCallHandler(Tin request, out Tout response);
    }
}

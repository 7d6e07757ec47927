// A runnable, test-only stand-in for the few UnityEngine APIs the generated scripts and ROS#'s
// RosConnector use. Signatures follow Unity's scripting API; what it models, and only that:
// - GameObject.AddComponent<T>() calls Awake at once (as Unity does for an active object);
//   Object.Destroy calls OnDestroy; FindObjectOfType/GetComponent search live components.
// - Player.Frame() is one frame of Unity's loop on the calling (main) thread: Start for new
//   components (an IEnumerator Start runs as a coroutine: `yield return null` resumes next
//   frame), then Update, then the coroutines, as Unity orders them.
// - Time.time/deltaTime advance per frame by the wall-clock time since the previous frame;
//   Time.realtimeSinceStartup is wall-clock.
// - Debug.Log* print "[log|warning|error] message" to stdout and keep them in Debug.Messages.
// Not modelled: scenes, serialization, physics, disabled objects, coroutine yield instructions
// other than null.
using System;
using System.Collections;
using System.Collections.Generic;
using System.Diagnostics;
using System.Linq;
using System.Reflection;

namespace UnityEngine
{
    public class Object
    {
        internal static readonly List<Component> Live = new List<Component>();
        public string name { get; set; }

        public static T FindObjectOfType<T>() where T : Object
        {
            foreach (Component component in Live)
            {
                if (component is T found) return found;
            }
            return null;
        }

        public static T Instantiate<T>(T original) where T : Object
        {
            throw new NotSupportedException("no prefabs here: Resources.Load finds none");
        }

        public static void Destroy(Object obj)
        {
            var component = obj as Component;
            if (component == null || !Live.Remove(component)) return;
            component.gameObject.Components.Remove(component);
            Player.Invoke(component, "OnDestroy");
            component.destroyed = true;
        }

        public static implicit operator bool(Object exists)
        {
            var component = exists as Component;
            return !ReferenceEquals(exists, null) && (component == null || !component.destroyed);
        }
    }

    public sealed class GameObject : Object
    {
        internal readonly List<Component> Components = new List<Component>();

        public GameObject(string name) { this.name = name; }

        public SceneManagement.Scene scene { get { return new SceneManagement.Scene(); } }

        public T AddComponent<T>() where T : Component, new()
        {
            return AddComponent<T>(null);
        }

        // Test-only overload: `serialized` sets the field values Unity would have read from the
        // scene before Awake.
        public T AddComponent<T>(Action<T> serialized) where T : Component, new()
        {
            var component = new T();
            if (serialized != null) serialized(component);
            component.gameObject = this;
            Components.Add(component);
            Live.Add(component);
            Player.Invoke(component, "Awake");
            Player.Pending.Add(component);
            return component;
        }

        public T GetComponent<T>()
        {
            foreach (Component component in Components)
            {
                if (component is T found) return found;
            }
            return default(T);
        }
    }

    public class Component : Object
    {
        internal bool destroyed;
        public GameObject gameObject { get; internal set; }
        public T GetComponent<T>() { return gameObject.GetComponent<T>(); }
    }

    public class Behaviour : Component
    {
        public bool enabled { get; set; } = true;
        public bool isActiveAndEnabled { get { return enabled && !destroyed; } }
    }

    public class MonoBehaviour : Behaviour { }

    public static class Player
    {
        internal static readonly List<Component> Pending = new List<Component>();
        static readonly List<IEnumerator> coroutines = new List<IEnumerator>();
        static readonly Stopwatch clock = Stopwatch.StartNew();
        public static int FrameCount { get; private set; }

        internal static object Invoke(Component component, string method)
        {
            for (Type type = component.GetType(); type != null; type = type.BaseType)
            {
                MethodInfo found = type.GetMethod(method, BindingFlags.Instance | BindingFlags.Public | BindingFlags.NonPublic | BindingFlags.DeclaredOnly, null, Type.EmptyTypes, null);
                if (found != null) return found.Invoke(component, null);
            }
            return null;
        }

        static float lastFrame;

        // What Unity does before the first scene loads: every [RuntimeInitializeOnLoadMethod]
        // of the loaded assemblies runs (the connector's message classes register themselves).
        public static void Boot()
        {
            foreach (Assembly assembly in AppDomain.CurrentDomain.GetAssemblies())
            {
                Type[] types;
                try { types = assembly.GetTypes(); }
                catch (ReflectionTypeLoadException e) { types = e.Types.Where(t => t != null).ToArray(); }
                foreach (Type type in types)
                {
                    foreach (MethodInfo method in type.GetMethods(BindingFlags.Static | BindingFlags.Public | BindingFlags.NonPublic))
                    {
                        if (method.GetCustomAttributes(typeof(RuntimeInitializeOnLoadMethodAttribute), false).Length > 0)
                            method.Invoke(null, null);
                    }
                }
            }
        }

        public static void Frame()
        {
            float now = Seconds;
            Time.deltaTime = now - lastFrame;
            Time.time += Time.deltaTime;
            lastFrame = now;
            var running = new List<IEnumerator>(coroutines);
            var starting = new List<Component>(Pending);
            Pending.Clear();
            foreach (Component component in starting)
            {
                if (component.destroyed) continue;
                var routine = Invoke(component, "Start") as IEnumerator;
                if (routine != null && routine.MoveNext()) coroutines.Add(routine);
            }
            foreach (Component component in new List<Component>(Object.Live))
            {
                if (!starting.Contains(component)) Invoke(component, "Update");
            }
            foreach (IEnumerator routine in running)
            {
                if (!routine.MoveNext()) coroutines.Remove(routine);
            }
            FrameCount++;
        }

        internal static float Seconds { get { return (float)clock.Elapsed.TotalSeconds; } }
    }

    public static class Time
    {
        public static float time { get; internal set; }
        public static float deltaTime { get; internal set; }
        public static float realtimeSinceStartup { get { return Player.Seconds; } }
    }

    public static class Debug
    {
        public static readonly List<string> Messages = new List<string>();

        static void Write(string level, object message)
        {
            string line = "[" + level + "] " + message;
            lock (Messages) Messages.Add(line);
            Console.WriteLine(line);
            Console.Out.Flush();
        }

        public static void Log(object message) { Write("log", message); }
        public static void Log(object message, Object context) { Write("log", message); }
        public static void LogWarning(object message) { Write("warning", message); }
        public static void LogWarning(object message, Object context) { Write("warning", message); }
        public static void LogError(object message) { Write("error", message); }
        public static void LogError(object message, Object context) { Write("error", message); }
        public static void LogException(Exception exception) { Write("exception", exception); }
    }

    // Unity calls these methods before the first scene's Start; Player.Boot does here.
    [AttributeUsage(AttributeTargets.Method)]
    public sealed class RuntimeInitializeOnLoadMethodAttribute : Attribute { }

    [AttributeUsage(AttributeTargets.Field)]
    public sealed class SerializeField : Attribute { }

    [AttributeUsage(AttributeTargets.Field)]
    public sealed class HideInInspector : Attribute { }

    [AttributeUsage(AttributeTargets.Field)]
    public sealed class TooltipAttribute : Attribute
    {
        public TooltipAttribute(string tooltip) { }
    }
}

namespace UnityEngine.SceneManagement
{
    public struct Scene
    {
        public string name { get { return "Main"; } }
    }
}

// A stand-in for the further parts of UnityEngine that ROS-TCP-Connector's Runtime/TcpConnector
// uses (its HUD, settings, prefab lookup and the JSON of its system commands), compiled together
// with UnityEngine.cs (compile-only) or tests/runtime/csharp/UnityEngineRuntime.cs (to run it).
// Signatures follow Unity's scripting API. What runs: JsonUtility for the flat structs the
// connector gives it, PlayerPrefs in memory, Resources.Load finding nothing (so
// GetOrCreateInstance falls back to a new GameObject), Application.isPlaying; the GUI types are
// there to compile (the connector draws only with its HUD shown) and do nothing.
using System;
using System.Collections.Generic;
using System.Globalization;
using System.Linq;
using System.Reflection;
using System.Text;

namespace UnityEngine
{
    public struct Vector2
    {
        public float x, y;
        public Vector2(float x, float y) { this.x = x; this.y = y; }
        public static Vector2 operator -(Vector2 a, Vector2 b) { return new Vector2(a.x - b.x, a.y - b.y); }
    }

    public struct Vector3
    {
        public float x, y, z;
        public Vector3(float x, float y, float z) { this.x = x; this.y = y; this.z = z; }
        public static Vector3 zero { get { return new Vector3(); } }
    }

    public struct Rect
    {
        public Rect(float x, float y, float width, float height) { this.x = x; this.y = y; this.width = width; this.height = height; }
        public float x { get; set; }
        public float y { get; set; }
        public float width { get; set; }
        public float height { get; set; }
        public float xMin { get { return x; } set { width += x - value; x = value; } }
        public float yMin { get { return y; } set { height += y - value; y = value; } }
        public float xMax { get { return x + width; } set { width = value - x; } }
        public float yMax { get { return y + height; } set { height = value - y; } }
        public bool Overlaps(Rect other) { return false; }
        public bool Contains(Vector2 point) { return false; }
    }

    public struct Color
    {
        public float r, g, b, a;
        public Color(float r, float g, float b) { this.r = r; this.g = g; this.b = b; a = 1f; }
        public Color(float r, float g, float b, float a) { this.r = r; this.g = g; this.b = b; this.a = a; }
        public static Color white { get { return new Color(1f, 1f, 1f); } }
        public static Color red { get { return new Color(1f, 0f, 0f); } }
        public static Color gray { get { return new Color(0.5f, 0.5f, 0.5f); } }
        public static Color Lerp(Color a, Color b, float t) { return a; }
    }

    public struct Quaternion
    {
        public static Quaternion identity { get { return new Quaternion(); } }
    }

    public static class Mathf
    {
        public static float Max(float a, float b) { return a > b ? a : b; }
    }

    public static class Screen
    {
        public static int width { get { return 0; } }
        public static int height { get { return 0; } }
    }

    public static class Application
    {
        public static bool isPlaying { get { return true; } }
    }

    // As Unity's, for what the connector gives it (SysCommand.cs): the public fields of a flat
    // struct, of types string, int, bool and string[], in declaration order.
    public static class JsonUtility
    {
        public static string ToJson(object obj)
        {
            var parts = new List<string>();
            foreach (FieldInfo field in obj.GetType().GetFields(BindingFlags.Public | BindingFlags.Instance))
            {
                parts.Add(Quote(field.Name) + ":" + Value(field.GetValue(obj)));
            }
            return "{" + string.Join(",", parts) + "}";
        }

        public static T FromJson<T>(string json)
        {
            object result = Activator.CreateInstance(typeof(T));
            int at = 0;
            Expect(json, ref at, '{');
            while (Skip(json, ref at) != '}')
            {
                string name = ReadString(json, ref at);
                Expect(json, ref at, ':');
                object value = ReadValue(json, ref at);
                FieldInfo field = typeof(T).GetField(name, BindingFlags.Public | BindingFlags.Instance);
                if (field != null) field.SetValue(result, Convert(value, field.FieldType));
                if (Skip(json, ref at) == ',') at++;
            }
            return (T)result;
        }

        static string Value(object value)
        {
            if (value == null) return "\"\"";
            if (value is bool b) return b ? "true" : "false";
            if (value is int i) return i.ToString(CultureInfo.InvariantCulture);
            if (value is string[] items) return "[" + string.Join(",", items.Select(Quote)) + "]";
            return Quote(value.ToString());
        }

        static string Quote(string text)
        {
            var builder = new StringBuilder("\"");
            foreach (char c in text)
            {
                if (c == '"' || c == '\\') builder.Append('\\').Append(c);
                else if (c < ' ') builder.Append("\\u").Append(((int)c).ToString("x4"));
                else builder.Append(c);
            }
            return builder.Append('"').ToString();
        }

        static object Convert(object value, Type type)
        {
            if (type == typeof(int)) return System.Convert.ToInt32(value, CultureInfo.InvariantCulture);
            if (type == typeof(string[])) return ((List<object>)value).Select(v => (string)v).ToArray();
            return value;
        }

        static char Skip(string json, ref int at)
        {
            while (char.IsWhiteSpace(json[at])) at++;
            return json[at];
        }

        static void Expect(string json, ref int at, char wanted)
        {
            if (Skip(json, ref at) != wanted) throw new ArgumentException("JSON: expected " + wanted + " at " + at);
            at++;
        }

        static object ReadValue(string json, ref int at)
        {
            char c = Skip(json, ref at);
            if (c == '"') return ReadString(json, ref at);
            if (c == '[')
            {
                var items = new List<object>();
                at++;
                while (Skip(json, ref at) != ']')
                {
                    items.Add(ReadValue(json, ref at));
                    if (Skip(json, ref at) == ',') at++;
                }
                at++;
                return items;
            }
            int start = at;
            while (at < json.Length && ",}] \t\r\n".IndexOf(json[at]) < 0) at++;
            string word = json.Substring(start, at - start);
            if (word == "true" || word == "false") return word == "true";
            return double.Parse(word, CultureInfo.InvariantCulture);
        }

        static string ReadString(string json, ref int at)
        {
            Expect(json, ref at, '"');
            var builder = new StringBuilder();
            while (json[at] != '"')
            {
                char c = json[at++];
                if (c != '\\') { builder.Append(c); continue; }
                char e = json[at++];
                if (e == 'u') { builder.Append((char)System.Convert.ToInt32(json.Substring(at, 4), 16)); at += 4; }
                else builder.Append(e == 'n' ? '\n' : e == 't' ? '\t' : e == 'r' ? '\r' : e == 'b' ? '\b' : e == 'f' ? '\f' : e);
            }
            at++;
            return builder.ToString();
        }
    }

    // As Unity's, without the disk: values live for the run.
    public static class PlayerPrefs
    {
        static readonly Dictionary<string, object> values = new Dictionary<string, object>();
        public static bool HasKey(string key) { return values.ContainsKey(key); }
        public static string GetString(string key, string defaultValue) { return values.TryGetValue(key, out object v) ? (string)v : defaultValue; }
        public static int GetInt(string key, int defaultValue) { return values.TryGetValue(key, out object v) ? (int)v : defaultValue; }
        public static void SetString(string key, string value) { values[key] = value; }
        public static void SetInt(string key, int value) { values[key] = value; }
    }

    public static class Resources
    {
        public static T Load<T>(string path) where T : Object { return null; }
    }

    public class ScriptableObject : Object { }

    public enum FontStyle { Normal, Bold, Italic, BoldAndItalic }
    public enum TextAnchor { UpperLeft, UpperCenter, UpperRight, MiddleLeft, MiddleCenter, MiddleRight, LowerLeft, LowerCenter, LowerRight }
    public enum EventType { MouseDown, MouseUp, MouseMove, MouseDrag, KeyDown, KeyUp, ScrollWheel, Repaint, Layout }

    public class RectOffset
    {
        public RectOffset() { }
        public RectOffset(int left, int right, int top, int bottom) { }
    }

    public class GUIStyleState
    {
        public Color textColor { get; set; }
    }

    public class GUIStyle
    {
        public GUIStyle() { }
        public GUIStyle(GUIStyle other) { }
        public FontStyle fontStyle { get; set; }
        public TextAnchor alignment { get; set; }
        public RectOffset padding { get; set; }
        public GUIStyleState normal { get; set; }
        public int fontSize { get; set; }
        public bool wordWrap { get; set; }
        public bool richText { get; set; }
        public int fixedWidth { get; set; }
    }

    public class GUIContent
    {
        public GUIContent(string text) { }
    }

    public class GUISkin
    {
        public GUIStyle box { get; set; }
        public GUIStyle button { get; set; }
        public GUIStyle label { get; set; }
    }

    public sealed class GUILayoutOption { }

    public class Event
    {
        public static Event current { get { return null; } }
        public EventType type { get; set; }
        public Vector2 mousePosition { get; set; }
        public int button { get; set; }
        public void Use() { }
    }

    public static class GUI
    {
        public delegate void WindowFunction(int id);
        public static Color color { get; set; }
        public static GUISkin skin { get { return null; } }
        public static void Label(Rect position, string text) { }
        public static void Label(Rect position, string text, GUIStyle style) { }
        public static bool Button(Rect position, string text) { return false; }
        public static Rect Window(int id, Rect clientRect, WindowFunction func, string text) { return clientRect; }
        public static void DragWindow() { }
    }

    public static class GUILayout
    {
        public static void Label(string text, params GUILayoutOption[] options) { }
        public static void Label(string text, GUIStyle style, params GUILayoutOption[] options) { }
        public static bool Button(string text, params GUILayoutOption[] options) { return false; }
        public static bool Toggle(bool value, string text, GUIStyle style, params GUILayoutOption[] options) { return value; }
        public static string TextField(string text, params GUILayoutOption[] options) { return text; }
        public static void Space(float pixels) { }
        public static void BeginHorizontal(params GUILayoutOption[] options) { }
        public static void EndHorizontal() { }
        public static void BeginVertical(GUIStyle style, params GUILayoutOption[] options) { }
        public static void EndVertical() { }
        public static Vector2 BeginScrollView(Vector2 scrollPosition, params GUILayoutOption[] options) { return scrollPosition; }
        public static void EndScrollView() { }
        public static GUILayoutOption Width(float width) { return null; }
        public static GUILayoutOption Height(float height) { return null; }
    }

    public static class GUILayoutUtility
    {
        public static Rect GetLastRect() { return new Rect(); }
    }
}

namespace UnityEngine.Serialization
{
    [AttributeUsage(AttributeTargets.Field, AllowMultiple = true)]
    public sealed class FormerlySerializedAsAttribute : Attribute
    {
        public FormerlySerializedAsAttribute(string oldName) { }
    }
}

namespace JetBrains.Annotations
{
    [AttributeUsage(AttributeTargets.All)]
    public sealed class NotNullAttribute : Attribute { }

    [AttributeUsage(AttributeTargets.All)]
    public sealed class CanBeNullAttribute : Attribute { }
}

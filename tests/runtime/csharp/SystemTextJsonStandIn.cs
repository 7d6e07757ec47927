// Test-only stand-in for the part of System.Text.Json that ROS# 2.2.1's ROS 2 build calls
// directly: Communicators.cs reads action feedback and results with
// JsonSerializer.Deserialize<T>(string), whatever serializer the RosSocket was given. The real
// System.Text.Json.dll (in ROS#'s Plugins/) needs System.Memory's Span APIs, which Debian's
// Mono 6.8 lacks, so it cannot run in these tests; this file is compiled into the test build of
// RosBridgeClient.dll in its place (tests/runtime/client.py, build_ros2_client).
//
// What it models, and only that: JsonSerializer's default contract when reading, as ROS# uses
// it (no options):
// - a class needs a public parameterless constructor; JSON object members are matched to public
//   instance properties with a public setter, by exact, case-sensitive name; public fields and
//   read-only properties are not set; JSON members with no such property are skipped;
// - strings only into string, true/false only into bool, JSON numbers only into numeric types
//   (no quoted numbers; a fraction or an out-of-range value into an integer type is refused);
// - byte[] from a base64 string; other arrays and List<T> from JSON arrays;
// - null into a reference type gives null, into a value type is refused.
// Anything refused throws JsonException, as the real one does. Not modelled: options, naming
// policies, attributes, enums, dictionaries, polymorphism, writing.
using System;
using System.Collections;
using System.Collections.Generic;
using System.Globalization;
using System.Reflection;
using Newtonsoft.Json.Linq;

namespace System.Text.Json
{
    public sealed class JsonSerializerOptions { }

    public class JsonException : Exception
    {
        public JsonException(string message) : base(message) { }
    }

    public static class JsonSerializer
    {
        public static T Deserialize<T>(string json, JsonSerializerOptions options = null)
        {
            JToken token;
            try
            {
                token = JToken.Parse(json);
            }
            catch (Newtonsoft.Json.JsonReaderException e)
            {
                throw new JsonException(e.Message);
            }
            return (T)Read(token, typeof(T), "$");
        }

        static object Read(JToken token, Type type, string path)
        {
            if (token.Type == JTokenType.Null)
            {
                if (!type.IsValueType || Nullable.GetUnderlyingType(type) != null) return null;
                throw Refused(path, type, token);
            }
            type = Nullable.GetUnderlyingType(type) ?? type;
            if (type == typeof(string))
            {
                if (token.Type != JTokenType.String) throw Refused(path, type, token);
                return (string)token;
            }
            if (type == typeof(bool))
            {
                if (token.Type != JTokenType.Boolean) throw Refused(path, type, token);
                return (bool)token;
            }
            if (type.IsPrimitive || type == typeof(decimal)) return Number(token, type, path);
            if (type == typeof(byte[]))
            {
                if (token.Type != JTokenType.String) throw Refused(path, type, token);
                try { return Convert.FromBase64String((string)token); }
                catch (FormatException) { throw Refused(path, type, token); }
            }
            if (type.IsArray) return Array(token, type.GetElementType(), path);
            if (type.IsGenericType && type.GetGenericTypeDefinition() == typeof(List<>))
            {
                var list = (IList)Activator.CreateInstance(type);
                foreach (object item in Array(token, type.GetGenericArguments()[0], path)) list.Add(item);
                return list;
            }
            return Object(token, type, path);
        }

        static object Number(JToken token, Type type, string path)
        {
            if (token.Type != JTokenType.Integer && token.Type != JTokenType.Float) throw Refused(path, type, token);
            bool integral = type != typeof(float) && type != typeof(double) && type != typeof(decimal);
            if (integral && token.Type == JTokenType.Float) throw Refused(path, type, token);
            try
            {
                return Convert.ChangeType(((JValue)token).Value, type, CultureInfo.InvariantCulture);
            }
            catch (OverflowException)
            {
                throw Refused(path, type, token);
            }
        }

        static System.Array Array(JToken token, Type element, string path)
        {
            if (token.Type != JTokenType.Array) throw Refused(path, element.MakeArrayType(), token);
            var items = (JArray)token;
            System.Array array = System.Array.CreateInstance(element, items.Count);
            for (int i = 0; i < items.Count; i++) array.SetValue(Read(items[i], element, path + "[" + i + "]"), i);
            return array;
        }

        static object Object(JToken token, Type type, string path)
        {
            if (token.Type != JTokenType.Object) throw Refused(path, type, token);
            if (type.GetConstructor(Type.EmptyTypes) == null)
            {
                throw new NotSupportedException("no public parameterless constructor on " + type);
            }
            object instance = Activator.CreateInstance(type);
            foreach (JProperty member in ((JObject)token).Properties())
            {
                PropertyInfo property = type.GetProperty(member.Name, BindingFlags.Public | BindingFlags.Instance);
                if (property == null || property.GetSetMethod() == null || property.GetIndexParameters().Length > 0) continue;
                property.SetValue(instance, Read(member.Value, property.PropertyType, path + "." + member.Name));
            }
            return instance;
        }

        static JsonException Refused(string path, Type type, JToken token)
        {
            return new JsonException("The JSON value could not be converted to " + type + ". Path: " + path + " (" + token.Type + ")");
        }
    }
}

namespace System.Text.Json.Serialization
{
    // ROS#'s Communication.cs imports this namespace (for nothing it uses in this build).
    internal static class NamespacePresent { }
}

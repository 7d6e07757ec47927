// Checks connector message classes against reference bytes (genpy's serialize for ROS 1, rclpy's
// serialize_message for ROS 2), with the connector's real MessageSerializer and
// MessageDeserializer. One case per input line, tab-separated:
//   class  label  reference-hex  padding-mask-hex-or-minus  payload-end  values-json
// Values are JSON of objects, arrays and strings only: integers in decimal, floats as the hex
// of their IEEE bits (NaN payloads and -0.0 exact), bools "1"/"0". For each case it prints
//   label  OK|FAIL <reasons>  our-bytes-hex
// SER: the instance built from the values serializes to the reference (padding must be zero,
// and may hold anything in the reference). DES: the class's Deserialize reads the reference,
// consumes the payload exactly, and gives the same values. DEFAULT (labels ending "default"):
// a default-constructed instance serializes to the reference too.
using System;
using System.Collections;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Reflection;
using System.Text;
using Unity.Robotics.ROSTCPConnector.MessageGeneration;

public static class WireCheck
{
    const BindingFlags Instance = BindingFlags.Public | BindingFlags.Instance;

    // args: cases file, verdicts file, then the assemblies that hold the classes.
    public static int Main(string[] args)
    {
        for (int i = 2; i < args.Length; i++)
            Assembly.LoadFrom(args[i]);
        var output = new StringBuilder();
        foreach (string line in File.ReadAllLines(args[0], Encoding.UTF8))
        {
            string[] parts = line.Split('\t');
            string verdict, ours = "";
            try
            {
                verdict = Check(parts, out ours);
            }
            catch (Exception e)
            {
                Exception inner = e is TargetInvocationException ? e.InnerException : e;
                verdict = "FAIL " + inner.GetType().Name + ": " + inner.Message.Replace('\n', ' ');
            }
            output.Append(parts[1]).Append('\t').Append(verdict).Append('\t').Append(ours).Append('\n');
        }
        File.WriteAllText(args[1], output.ToString());
        return 0;
    }

    static Type FindType(string name)
    {
        foreach (Assembly assembly in AppDomain.CurrentDomain.GetAssemblies())
        {
            Type found = assembly.GetType(name);
            if (found != null)
                return found;
        }
        throw new ArgumentException("no class " + name);
    }

    static string Check(string[] parts, out string oursHex)
    {
        Type type = FindType(parts[0]);
        byte[] reference = FromHex(parts[2]);
        byte[] mask = parts[3] == "-" ? new byte[reference.Length] : FromHex(parts[3]);
        int end = int.Parse(parts[4], CultureInfo.InvariantCulture);
        Message built = (Message)Build(type, Json.Parse(parts[5]));
        var problems = new List<string>();
        byte[] ours = Serialize(built);
        oursHex = ToHex(ours);
        string difference = Differs(ours, reference, mask, end);
        if (difference != null)
            problems.Add("SER " + difference);
        var deserializer = new MessageDeserializer();
        deserializer.InitWithBuffer(reference);
        MethodInfo read = type.GetMethod("Deserialize", BindingFlags.Public | BindingFlags.Static, null, new[] { typeof(MessageDeserializer) }, null);
        object back = read.Invoke(null, new object[] { deserializer });
        int offset = (int)typeof(MessageDeserializer).GetField("offset", BindingFlags.NonPublic | BindingFlags.Instance).GetValue(deserializer);
        if (offset != end)
            problems.Add("DES read " + offset + " of " + end + " bytes");
        string unequal = Unequal(built, back, type.Name);
        if (unequal != null)
            problems.Add("DES " + unequal);
        if (parts[1].EndsWith("default", StringComparison.Ordinal))
        {
            string fresh = Differs(Serialize((Message)Activator.CreateInstance(type)), reference, mask, end);
            if (fresh != null)
                problems.Add("DEFAULT " + fresh);
        }
        return problems.Count == 0 ? "OK" : "FAIL " + string.Join("; ", problems.ToArray());
    }

    static byte[] Serialize(Message message)
    {
        var serializer = new MessageSerializer();
        serializer.SerializeMessage(message);
        return serializer.GetBytes();
    }

    static string Differs(byte[] ours, byte[] reference, byte[] mask, int end)
    {
        if (ours.Length != end)
            return "length " + ours.Length + ", reference " + end;
        for (int i = 0; i < end; i++)
        {
            bool padding = mask[i] != 0;
            if (padding ? ours[i] != 0 : ours[i] != reference[i])
                return "byte " + i + (padding ? " (padding)" : "") + ": " + ours[i] + " vs " + reference[i];
        }
        return null;
    }

    static MemberInfo Member(Type type, string name)
    {
        foreach (BindingFlags extra in new[] { BindingFlags.Default, BindingFlags.IgnoreCase })
        {
            MemberInfo field = type.GetField(name, Instance | extra);
            if (field != null)
                return field;
            MemberInfo property = type.GetProperty(name, Instance | extra);
            if (property != null)
                return property;
        }
        throw new ArgumentException(type.Name + " has no member " + name);
    }

    static object Build(Type type, object value)
    {
        if (type.IsArray)
        {
            var items = (List<object>)value;
            Array array = Array.CreateInstance(type.GetElementType(), items.Count);
            for (int i = 0; i < items.Count; i++)
                array.SetValue(Build(type.GetElementType(), items[i]), i);
            return array;
        }
        if (type == typeof(string))
            return (string)value;
        if (type == typeof(bool))
            return (string)value == "1";
        if (type == typeof(float))
            return BitConverter.ToSingle(BitConverter.GetBytes(uint.Parse((string)value, NumberStyles.HexNumber)), 0);
        if (type == typeof(double))
            return BitConverter.Int64BitsToDouble(unchecked((long)ulong.Parse((string)value, NumberStyles.HexNumber)));
        if (type == typeof(sbyte)) // the connector's sbyte for ROS 2's octet, 0..255 in rclpy
            return unchecked((sbyte)long.Parse((string)value, CultureInfo.InvariantCulture));
        if (type.IsPrimitive)
            return Convert.ChangeType((string)value, type, CultureInfo.InvariantCulture);
        object message = Activator.CreateInstance(type);
        foreach (KeyValuePair<string, object> entry in (Dictionary<string, object>)value)
        {
            MemberInfo member = Member(type, entry.Key);
            var field = member as FieldInfo;
            if (field != null)
                field.SetValue(message, Build(field.FieldType, entry.Value));
            else
            {
                var property = (PropertyInfo)member;
                property.SetValue(message, Build(property.PropertyType, entry.Value), null);
            }
        }
        return message;
    }

    static string Unequal(object a, object b, string path)
    {
        if (a == null || b == null)
            return a == b ? null : path + " is null on one side";
        Type type = a.GetType();
        if (type != b.GetType())
            return path + ": " + type.Name + " vs " + b.GetType().Name;
        if (type == typeof(float))
            return BitConverter.ToInt32(BitConverter.GetBytes((float)a), 0) == BitConverter.ToInt32(BitConverter.GetBytes((float)b), 0) ? null : path + ": " + a + " vs " + b;
        if (type == typeof(double))
            return BitConverter.DoubleToInt64Bits((double)a) == BitConverter.DoubleToInt64Bits((double)b) ? null : path + ": " + a + " vs " + b;
        if (type.IsPrimitive || type == typeof(string))
            return a.Equals(b) ? null : path + ": " + a + " vs " + b;
        if (type.IsArray)
        {
            var x = (Array)a;
            var y = (Array)b;
            if (x.Length != y.Length)
                return path + ": " + x.Length + " vs " + y.Length + " elements";
            for (int i = 0; i < x.Length; i++)
            {
                string inner = Unequal(x.GetValue(i), y.GetValue(i), path + "[" + i + "]");
                if (inner != null)
                    return inner;
            }
            return null;
        }
        foreach (FieldInfo field in type.GetFields(Instance))
        {
            string inner = Unequal(field.GetValue(a), field.GetValue(b), path + "." + field.Name);
            if (inner != null)
                return inner;
        }
        foreach (PropertyInfo property in type.GetProperties(Instance))
        {
            if (property.GetIndexParameters().Length > 0 || !property.CanWrite)
                continue;
            string inner = Unequal(property.GetValue(a, null), property.GetValue(b, null), path + "." + property.Name);
            if (inner != null)
                return inner;
        }
        return null;
    }

    static byte[] FromHex(string hex)
    {
        var bytes = new byte[hex.Length / 2];
        for (int i = 0; i < bytes.Length; i++)
            bytes[i] = byte.Parse(hex.Substring(2 * i, 2), NumberStyles.HexNumber);
        return bytes;
    }

    static string ToHex(byte[] bytes)
    {
        var text = new StringBuilder(bytes.Length * 2);
        foreach (byte b in bytes)
            text.Append(b.ToString("x2"));
        return text.ToString();
    }
}

// JSON of objects, arrays and strings, as Python's json.dumps(ensure_ascii=True) writes them.
static class Json
{
    public static object Parse(string text)
    {
        int at = 0;
        return Value(text, ref at);
    }

    static object Value(string text, ref int at)
    {
        char c = text[at];
        if (c == '"')
            return Text(text, ref at);
        bool isObject = c == '{';
        at++;
        var list = new List<object>();
        var map = new Dictionary<string, object>();
        while (text[at] != (isObject ? '}' : ']'))
        {
            if (text[at] == ',' || text[at] == ' ')
            {
                at++;
                continue;
            }
            if (isObject)
            {
                string key = Text(text, ref at);
                at++; // ':'
                while (text[at] == ' ')
                    at++;
                map[key] = Value(text, ref at);
            }
            else
                list.Add(Value(text, ref at));
        }
        at++;
        return isObject ? (object)map : list;
    }

    static string Text(string text, ref int at)
    {
        var value = new StringBuilder();
        at++;
        while (text[at] != '"')
        {
            char c = text[at++];
            if (c != '\\')
            {
                value.Append(c);
                continue;
            }
            char e = text[at++];
            if (e == 'u')
            {
                value.Append((char)int.Parse(text.Substring(at, 4), NumberStyles.HexNumber));
                at += 4;
            }
            else
                value.Append(e == 'n' ? '\n' : e == 't' ? '\t' : e == 'r' ? '\r' : e == 'b' ? '\b' : e == 'f' ? '\f' : e);
        }
        at++;
        return value.ToString();
    }
}

// Test program: what System.Text.Json's default contract (no options: public instance
// properties with a public getter are written, those with a public setter are read, public
// fields are ignored, a public parameterless constructor is required to read) sees in every
// message class of an assembly. Prints one line per class deriving from ROS#'s Message:
// "Full.Class.Name<TAB>ctor|NOCTOR<TAB>prop1,prop2,...<TAB>field1,field2,..." where props are
// the read-write properties and fields the public instance fields (which STJ would skip).
using System;
using System.Linq;
using System.Reflection;

public static class StjContract
{
    public static int Main(string[] args)
    {
        Assembly assembly = Assembly.LoadFrom(args[0]);
        Type message = assembly.GetType("RosSharp.RosBridgeClient.Message", true);
        foreach (Type type in assembly.GetTypes().Where(t => t.IsSubclassOf(message) && !t.IsAbstract).OrderBy(t => t.FullName))
        {
            bool constructor = type.GetConstructor(Type.EmptyTypes) != null;
            var properties = type.GetProperties(BindingFlags.Public | BindingFlags.Instance)
                .Where(p => p.GetGetMethod() != null && p.GetSetMethod() != null && p.GetIndexParameters().Length == 0)
                .Select(p => p.Name).OrderBy(n => n, StringComparer.Ordinal);
            var fields = type.GetFields(BindingFlags.Public | BindingFlags.Instance).Select(f => f.Name).OrderBy(n => n, StringComparer.Ordinal);
            Console.WriteLine(type.FullName + "\t" + (constructor ? "ctor" : "NOCTOR") + "\t" + string.Join(",", properties) + "\t" + string.Join(",", fields));
        }
        return 0;
    }
}

// Reference values of .NET's System.Random(seed) for the Random, Jitter and Random Reduce nodes.
// Run with Mono (Debian packages mono-mcs and mono-runtime):
//   mcs tools/oracle/dotnet_random.cs -out:/tmp/r.exe && mono /tmp/r.exe
// and wrap the lines in {"generator": "System.Random (Mono 6.8)", "cases": [...]} as
// crates/nodes/tests/data/dotnet_random.json, with each double quoted as a string (JSON readers
// do not all round decimal text correctly).
using System;
class P { static void Main() {
  foreach (int seed in new int[]{0, 1, 2, 42, -7, 123456789, int.MaxValue, int.MinValue}) {
    var r = new Random(seed);
    Console.Write("{\"seed\": " + seed + ", \"doubles\": [");
    for (int i = 0; i < 8; i++) { if (i>0) Console.Write(", "); Console.Write(r.NextDouble().ToString("R")); }
    Console.Write("], \"next_0_10\": [");
    for (int i = 0; i < 8; i++) { if (i>0) Console.Write(", "); Console.Write(r.Next(0, 10)); }
    Console.Write("], \"next_min_max\": [");
    for (int i = 0; i < 4; i++) { if (i>0) Console.Write(", "); Console.Write(r.Next(int.MinValue, int.MaxValue)); }
    Console.WriteLine("]}");
  }
}}

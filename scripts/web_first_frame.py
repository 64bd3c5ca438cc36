#!/usr/bin/env python3
"""Where the browser's first frame goes with the CPU slowed: serves DIST (built by
scripts/web) from /phonglab/, loads it RUNS times in headless Chromium with the CPU slowed
RATE times and the HTTP cache off (as scripts/web_test.py's check 12), and prints for each
load the page's own clock (performance.now(), ms from navigation) at: the page's script,
the wasm's first and last byte, WebAssembly.instantiateStreaming's start and end (the
compile overlaps the download), and the first frame the app counts (its probe's
`frames`). With --profile the last load runs under the DevTools sampling profiler too and
the functions with the most time under them (inclusive) are printed (their names only in a
dist/ built without wasm-opt, `NO_WASM_OPT=1 scripts/web`: wasm-opt drops the name section).
Usage: scripts/web_first_frame.py [DIST] [--rate RATE] [--runs RUNS] [--profile]
"""
import collections
import os
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import web_test as w  # noqa: E402  (the driver and the probe's helpers)

# Marks the page's clock when the page starts and around the wasm's compile.
HOOK = r"""
window.__marks = [['script', performance.now()]];
const orig = WebAssembly.instantiateStreaming;
WebAssembly.instantiateStreaming = async function (...a) {
  window.__marks.push(['instantiate start', performance.now()]);
  const r = await orig.apply(this, a);
  window.__marks.push(['instantiate end', performance.now()]);
  return r;
};
"""


def inclusive_times(profile):
    """ms under each function (each sample counted once per function on its stack)."""
    nodes = {n["id"]: n for n in profile["nodes"]}
    parent = {c: n["id"] for n in profile["nodes"] for c in n.get("children", [])}
    total = collections.Counter()
    for sample, dt in zip(profile["samples"], profile["timeDeltas"]):
        seen, node = set(), sample
        while node is not None:
            name = nodes[node]["callFrame"]["functionName"] or "(anonymous)"
            if name not in seen:
                seen.add(name)
                total[name] += dt / 1000
            node = parent.get(node)
    return total


def main():
    args = sys.argv[1:]
    dist = args[0] if args and not args[0].startswith("--") else "dist"
    rate = int(args[args.index("--rate") + 1]) if "--rate" in args else 4
    runs = int(args[args.index("--runs") + 1]) if "--runs" in args else 3
    profile = "--profile" in args
    with w.served(dist) as (url, d):
        for run in range(runs):
            d.go("about:blank")
            d.cdp("Network.enable")
            d.cdp("Network.setCacheDisabled", {"cacheDisabled": True})
            d.cdp("Page.enable")
            hook = d.cdp("Page.addScriptToEvaluateOnNewDocument", {"source": HOOK})["identifier"]
            d.cdp("Emulation.setCPUThrottlingRate", {"rate": rate})
            profiled = profile and run == runs - 1
            if profiled:
                d.cdp("Profiler.enable")
                d.cdp("Profiler.setSamplingInterval", {"interval": 500})
                d.cdp("Profiler.start")
            d.go(url)
            w.wait_probe(d, lambda q: q["frames"] >= 1, "a first frame", 120)
            frame = d.js("return performance.now();")
            marks, wasm = d.js(
                "return [window.__marks, performance.getEntriesByType('resource')"
                ".filter(r => r.name.endsWith('.wasm')).map(r => [r.responseStart, r.responseEnd])[0]];")
            d.cdp("Emulation.setCPUThrottlingRate", {"rate": 1})
            d.cdp("Page.removeScriptToEvaluateOnNewDocument", {"identifier": hook})
            at = dict(marks)
            print(f"load {run + 1}, CPU slowed {rate}x: script {at['script']:.0f} ms, wasm bytes "
                  f"{wasm[0]:.0f}-{wasm[1]:.0f}, instantiate {at['instantiate start']:.0f}-"
                  f"{at['instantiate end']:.0f}, first frame seen by {frame:.0f} ms")
            if profiled:
                times = inclusive_times(d.cdp("Profiler.stop")["profile"])
                for name, ms in times.most_common(60):
                    print(f"  {ms:7.0f} ms  {name[:140]}")


if __name__ == "__main__":
    main()

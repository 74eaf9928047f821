#!/usr/bin/env python3
"""Load and faults for `gnss-cli serve` (docs/reliability.md, "Serving: load and faults").

    nice -n 19 python3 tests/reliability/serve_load.py [--clients 50] [--minutes 10] [--quick]

By hand, not in ctest or CI; 127.0.0.1 only; bounded in time; exit 1 when a check fails. The
stream: gnss-sim --rtcm-base as a recording paced at --rate KiB/s, served with --replay --loop by
a caster with a password and a raw port. Every client's bytes (NTRIP 2: de-chunked) must be one
contiguous run of the file played over and over; silent clients must be dropped while the others
lose nothing; bad requests must get their replies and disturb nobody. Standard library only.
"""
import argparse, asyncio, base64, os, random, re, signal, socket, subprocess, sys
import tempfile, threading, time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
MOUNT, USER, PASSWORD = "LOAD", "load", "serve-load-pw"
K = 4096  # a client's first K bytes place it in the stream


def make_stream(sim, rate, loop_s, path):
    """RTCM 3 frames of gnss-sim --rtcm-base (whole ones), one index record each, `rate` B/s."""
    want = rate * loop_s
    out = subprocess.run([sim, "--rtcm-base", "--stdout", "--speed", "1000", "--duration",
                          str(want // 200 + 60)], stdin=subprocess.DEVNULL,
                         stdout=subprocess.PIPE, check=True).stdout
    frames, off = [], 0
    while off < want and off + 6 <= len(out) and out[off] == 0xD3:
        n = (((out[off + 1] & 3) << 8) | out[off + 2]) + 6
        frames.append((off, n))
        off += n
    if off < want or off > len(out):
        sys.exit("serve_load: gnss-sim's output is not RTCM 3 (byte %d)" % off)
    with open(path, "wb") as f:
        f.write(out[:off])
    with open(path + ".idx", "w") as f:
        f.write("# gnss-workbench recording index 1 (docs/recording.md)\n")
        f.writelines("R %d %d %d\n" % (1_700_000_000_000 + o * 1000 // rate, o, n)
                     for o, n in frames)
    return out[:off]


class Check:
    """The bytes fed must be one contiguous run of `data` repeated."""
    def __init__(self, data):
        self.data, self.pos, self.head, self.n, self.error = data, None, b"", 0, None

    def feed(self, b):
        self.n += len(b)
        if self.error or not b:
            return
        if self.pos is None:
            self.head += b
            if len(self.head) < K:
                return
            ring = self.data + self.data[:K - 1]
            at = ring.find(self.head[:K])
            if at < 0 or ring.find(self.head[:K], at + 1) >= 0:
                self.error = "first %d bytes: %s in the stream" % (K, "twice" if at >= 0 else "not")
                return
            self.pos, b, self.head = at, self.head, b""
        d, i, start = self.data, 0, self.n - len(b)
        while i < len(b):
            m = min(len(b) - i, len(d) - self.pos)
            if b[i:i + m] != d[self.pos:self.pos + m]:
                j = next(k for k in range(m) if b[i + k] != d[self.pos + k])
                self.error = "byte %d differs from the stream (file offset %d)" % (
                    start + i + j, self.pos + j)
                return
            i, self.pos = i + m, (self.pos + m) % len(d)

    def done(self):
        return self.error or (None if self.pos is not None else "only %d bytes received" % self.n)


class Dechunk:
    """HTTP/1.1 chunked body → its bytes (a chunk is handed on once whole)."""
    def __init__(self):
        self.buf, self.error = b"", None

    def feed(self, b):
        self.buf, out = self.buf + b, []
        while (nl := self.buf.find(b"\r\n")) >= 0:
            try:
                size = int(self.buf[:nl], 16)
            except ValueError:
                self.error = "chunk size %r" % self.buf[:nl][:40]
                break
            end = nl + 2 + size
            if len(self.buf) < end + 2 or not size:
                break
            if self.buf[end:end + 2] != b"\r\n":
                self.error = "no CR LF after a chunk of %d bytes" % size
                break
            out.append(self.buf[nl + 2:end])
            self.buf = self.buf[end + 2:]
        if nl < 0 and len(self.buf) > 32:
            self.error = "a chunk size line longer than 32 bytes"
        return b"".join(out)


def request(v2, mount=MOUNT, user=USER, password=PASSWORD):
    h = "GET /%s HTTP/1.%d\r\nUser-Agent: NTRIP serve_load\r\n" % (mount, v2)
    if v2:
        h += "Host: 127.0.0.1\r\nNtrip-Version: Ntrip/2.0\r\nConnection: close\r\n"
    if user:
        h += "Authorization: Basic %s\r\n" % base64.b64encode(
            ("%s:%s" % (user, password)).encode()).decode()
    return (h + "\r\n").encode()


BAD = [  # what, bytes sent, the reply's first line starts with ("": closed without a reply)
    ("malformed request line", b"HELLO\r\n\r\n", "HTTP/1.0 400"),
    ("binary garbage", random.Random(1).randbytes(512) + b"\r\n\r\n", "HTTP/1.0 400"),
    ("head over 8 KiB", b"GET /LOAD HTTP/1.0\r\n" + b"X-Pad: %s\r\n" % (b"a" * 1000) * 9 + b"\r\n",
     "HTTP/1.0 400"),
    ("POST", b"POST /LOAD HTTP/1.0\r\n\r\n", "HTTP/1.0 405"),
    ("no password, v1", request(0, user=None), "HTTP/1.0 401"),
    ("wrong password, v1", request(0, password="wrong"), "HTTP/1.0 401"),
    ("wrong password, v2", request(1, password="wrong"), "HTTP/1.1 401"),
    ("unknown mountpoint, v1", request(0, mount="NOPE"), "SOURCETABLE 200 OK"),
    ("unknown mountpoint, v2", request(1, mount="NOPE"), "HTTP/1.1 404"),
    ("no request at all", b"", ""),
]


async def client(kind, port, data, run_s, res):
    """Reads for run_s seconds from its first byte; res gets bytes, seconds, silence, error."""
    loop = asyncio.get_running_loop()
    r, w = await asyncio.open_connection("127.0.0.1", port)
    check, dechunk, t0 = Check(data), Dechunk() if kind == "v2" else None, None
    try:
        if kind != "raw":
            w.write(request(kind == "v2"))
            head = (await asyncio.wait_for(r.readuntil(b"\r\n\r\n"), 10)).decode("latin-1")
            if not head.startswith("ICY 200 OK" if kind == "v1" else "HTTP/1.1 200 OK") or (
                    dechunk and "Transfer-Encoding: chunked" not in head):
                res["error"] = "answered %r" % head[:60]
                return
        while t0 is None or (now := loop.time()) < t0 + run_s:
            try:
                b = await asyncio.wait_for(r.read(1 << 16), (t0 + run_s - now) if t0 else 30)
            except asyncio.TimeoutError:
                break
            if not b:
                res["error"] = "closed by the server after %d bytes" % check.n
                break
            now = loop.time()
            t0, last = (t0, last) if t0 is not None else (now, now)
            res["silence"], last = max(res["silence"], now - last), now
            check.feed(dechunk.feed(b) if dechunk else b)
            if check.error or (dechunk and dechunk.error):
                res["error"] = dechunk and dechunk.error
                break
        if t0 is not None:
            res["seconds"] = min(loop.time(), t0 + run_s) - t0
            res["silence"] = max(res["silence"], t0 + res["seconds"] - last)
        res["error"] = res["error"] or check.done()
    except (OSError, asyncio.IncompleteReadError, asyncio.TimeoutError) as e:
        res["error"] = "%s: %s" % (type(e).__name__, e)
    finally:
        res["bytes"] = check.n
        w.close()


async def bad_request(port, what, sent, want, tally, fails):
    t = time.monotonic()
    try:
        r, w = await asyncio.open_connection("127.0.0.1", port)
        w.write(sent)
        reply = await asyncio.wait_for(r.read(), 15)
        w.close()
    except (OSError, asyncio.TimeoutError) as e:
        reply = type(e).__name__.encode()
    first = reply.split(b"\r\n")[0].decode("latin-1")
    got = first if reply else "closed after %.0f s without a reply" % (time.monotonic() - t)
    tally[(what, got)] = tally.get((what, got), 0) + 1
    if not first.startswith(want) or (not want and reply):
        fails.append("%s: got %r" % (what, got))


def cpu_and_rss(pid):
    """(time, user+system CPU seconds, VmHWM kB) of a running process, from /proc."""
    with open("/proc/%d/stat" % pid) as f:
        fields = f.read().rsplit(")", 1)[1].split()
    with open("/proc/%d/status" % pid) as f:
        hwm = int(re.search(r"VmHWM:\s+(\d+)", f.read()).group(1))
    return time.monotonic(), (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK"), hwm


async def silent_client(what, port, req, said, data, end):
    """Connects, reads nothing until the server drops it, then reads what its socket holds."""
    s = socket.socket()
    s.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 4096)
    s.connect(("127.0.0.1", port))
    s.sendall(req)
    res = dict(what=what, drop=None, why="not dropped within the run", sent=0, got=0, error=None)
    t, me = time.monotonic(), re.compile(
        r"client 127\.0\.0\.1:%d disconnected: (.*) \((\d+) bytes sent\)" % s.getsockname()[1])
    while res["drop"] is None and time.monotonic() < end:
        await asyncio.sleep(0.2)
        for t_line, m in ((t_line, me.search(l)) for t_line, l in list(said)):
            if m:
                res.update(drop=t_line - t, why=m.group(1), sent=int(m.group(2)))
    if res["drop"] is not None:  # at once: the kernel resets an orphaned connection after a while
        s.setblocking(False)
        chunks, check = [], Check(data)
        try:
            while b := await asyncio.wait_for(asyncio.get_running_loop().sock_recv(s, 1 << 20), 10):
                chunks.append(b)
            got = b"".join(chunks)
            check.feed(got.split(b"\r\n\r\n", 1)[1] if req else got)
            res["error"] = check.done()
        except (OSError, asyncio.TimeoutError) as e:
            res["error"] = "then %s" % (str(e) or type(e).__name__)
        res["got"] = sum(map(len, chunks))
    s.close()
    return res


async def run(a, data, ntrip, raw, proc, said):
    kinds = ["raw" if i % 5 == 4 else ("v1", "v2")[i % 5 % 2] for i in range(a.clients)]
    results = [dict(kind=k, silence=0.0, seconds=0.0, bytes=0, error=None) for k in kinds]
    tasks, cpu0 = [], cpu_and_rss(proc.pid)
    for k, res in zip(kinds, results):
        port = raw if k == "raw" else ntrip
        tasks.append(asyncio.ensure_future(client(k, port, data, a.run_s, res)))
        await asyncio.sleep(0.05)
    end = time.monotonic() + a.run_s - 8
    silent = asyncio.gather(silent_client("NTRIP 1", ntrip, request(0), said, data, end),
                            silent_client("raw", raw, b"", said, data, end))
    tally, fails, rounds = {}, [], 0
    while time.monotonic() < end:
        rounds += 1
        await asyncio.gather(*(bad_request(ntrip, *b, tally, fails) for b in BAD))
        await asyncio.sleep(a.every)
    await asyncio.gather(*tasks)
    return results, await silent, tally, fails, rounds, cpu0, cpu_and_rss(proc.pid)


def start_server(a, path):
    """gnss-cli serve on free ports: the process, its stderr lines as (time, text), the ports."""
    cmd = [a.cli, "serve", "--replay", path, "--loop", "--ntrip", "127.0.0.1:0/" + MOUNT,
           "--user", USER, "--password-env", "SERVE_LOAD_PW", "--raw", "127.0.0.1:0",
           "--duration", str(int(a.run_s + a.clients * 0.05 + 15))]
    proc = subprocess.Popen(cmd, env=dict(os.environ, SERVE_LOAD_PW=PASSWORD),
                            stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                            stderr=subprocess.PIPE)
    said, ports, t = [], {}, time.monotonic()

    def pump():
        for line in proc.stderr:
            said.append((time.monotonic(), line.decode("utf-8", "replace").rstrip()))
    threading.Thread(target=pump, daemon=True).start()
    while len(ports) < 2 and time.monotonic() < t + 20:
        for _, line in said:
            if m := re.search(r"(NTRIP caster|raw stream) on 127\.0\.0\.1:(\d+)", line):
                ports[m.group(1)] = int(m.group(2))
        time.sleep(0.05)
    return proc, said, ports


def stop_server(proc, wait_s):
    """(exit status, rusage): ended by --duration within wait_s, else SIGTERM, then SIGKILL."""
    for sig in (None, signal.SIGTERM, signal.SIGKILL):
        if sig:
            os.kill(proc.pid, sig)  # not proc.send_signal: it would reap, and rusage with it
        t = time.monotonic()
        while time.monotonic() < t + (3 if sig else wait_s):
            pid, st, ru = os.wait4(proc.pid, os.WNOHANG)
            if pid:
                proc.returncode = os.waitstatus_to_exitcode(st)
                return (proc.returncode if sig is None else "stopped by " + sig.name), ru
            time.sleep(0.1)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--clients", type=int, default=50)
    p.add_argument("--minutes", type=float, default=10)
    p.add_argument("--quick", action="store_true", help="30 s instead of --minutes")
    p.add_argument("--rate", type=int, default=256, help="KiB/s of the stream (default 256)")
    p.add_argument("--cli", default=os.path.join(ROOT, "build/dev/app/cli/gnss-cli"))
    p.add_argument("--sim", default=os.path.join(ROOT, "build/dev/app/sim/gnss-sim"))
    a = p.parse_args()
    for sig in (signal.SIGINT, signal.SIGTERM):  # the server is stopped below on either
        signal.signal(sig, signal.default_int_handler)
    a.run_s, a.every = (30, 5) if a.quick else (a.minutes * 60, 10)
    rate = a.rate * 1024
    tmp = tempfile.TemporaryDirectory(prefix="serve_load.")
    path = os.path.join(tmp.name, "load.rtcm")
    data = make_stream(a.sim, rate, 10, path)
    proc, said, ports = start_server(a, path)
    wait_s = 0  # on an exception the server is stopped at once
    try:
        if len(ports) < 2:
            sys.exit("serve_load: the server did not say where it listens:\n" +
                     "\n".join(l for _, l in said))
        results, silent, tally, fails, rounds, c0, c1 = asyncio.run(
            run(a, data, ports["NTRIP caster"], ports["raw stream"], proc, said))
        wait_s = 60
    finally:
        status, usage = stop_server(proc, wait_s)
    time.sleep(0.2)  # the last lines of standard error
    n = {k: sum(r["kind"] == k for r in results) for k in ("v1", "v2", "raw")}
    print("serve_load: %d clients (NTRIP 1: %d, NTRIP 2: %d, raw: %d) for %.0f s each; stream "
          "%d B/s (%d bytes of gnss-sim --rtcm-base, looped every %.1f s); %d CPUs" % (
              a.clients, n["v1"], n["v2"], n["raw"], a.run_s, rate, len(data), len(data) / rate,
              os.cpu_count()))
    nb = [r["bytes"] for r in results]
    bps = [r["bytes"] / max(r["seconds"], 1e-9) for r in results]
    print("  bytes per client: min %d, mean %d, max %d; %.1f MB in all; per client %.0f to %.0f "
          "B/s" % (min(nb), sum(nb) / len(nb), max(nb), sum(nb) / 1e6, min(bps), max(bps)))
    worst = max(results, key=lambda r: r["silence"])
    print("  every byte in order: %d of %d clients; longest silence of a client %.3f s (%s)" % (
        sum(not r["error"] for r in results), len(results), worst["silence"], worst["kind"]))
    fails += ["client %d (%s): %s after %.1f s, %d bytes" % (
        i, r["kind"], r["error"] or "ended early", r["seconds"], r["bytes"])
        for i, r in enumerate(results) if r["error"] or r["seconds"] < a.run_s - 0.5]
    for r in silent:
        dropped = "dropped %.1f s after it connected" % r["drop"] if r["drop"] else "not dropped"
        print("  silent %s client (SO_RCVBUF 4096, reads nothing): %s (server: \"%s\", %d bytes "
              "sent); it then read %d bytes from its socket, %s" % (
                  r["what"], dropped, r["why"], r["sent"], r["got"],
                  r["error"] or "in order, then its end"))
        if "did not read" not in r["why"] or r["got"] < r["sent"] or r["error"]:
            fails.append("silent %s client: %s, %d bytes read (%s)" % (
                r["what"], r["why"], r["got"], r["error"]))
    print("  bad requests, %d rounds of %d during the run:" % (rounds, len(BAD)))
    for (what, got), k in sorted(tally.items()):
        print("    %-24s x%-4d %s" % (what, k, got))
    cpu, wall = c1[1] - c0[1], c1[0] - c0[0]
    print("  server: exit %s; CPU while the clients ran %.1f s in %.0f s = %.1f %% of one core; "
          "max RSS (VmHWM) %.1f MB; CPU in its whole life: user %.1f s + system %.1f s" % (
              status, cpu, wall, 100 * cpu / wall, c1[2] / 1024, usage.ru_utime, usage.ru_stime))
    summary = [l[len("gnss-cli: "):] for _, l in said if re.match(r"gnss-cli: (NTRIP|raw): ", l)]
    print("".join("  server said: %s\n" % l for l in summary), end="")
    m = re.search(r"dropped: (\d+) slow, (\d+) without.*raw: dropped (\d+) slow", " ".join(summary))
    if not m or m.groups() != ("1", str(rounds), "1"):
        fails.append("the server's counts: %r" % summary)
    if status != 0:
        fails.append("the server's exit status: %s" % status)
    print("".join("FAIL: %s\n" % f for f in fails) + "serve_load: " + ("FAIL" if fails else "PASS"))
    return 1 if fails else 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except KeyboardInterrupt:
        sys.exit("serve_load: interrupted, the server stopped")

#!/usr/bin/env python3
"""A site link shaped in user space, for kernels without sch_netem (scripts/multisite.sh).

    linkshaper.py A B B_NETNS DELAY_MS LOSS_PERCENT [SEED] [--jitter-ms J] [--dup P] [--reorder P]
                  [--one-way]

Creates two TAP devices A and B in the current network namespace, moves B into the namespace
B_NETNS (the open file keeps it attached), and forwards every Ethernet frame between them after
DELAY_MS milliseconds, dropping each frame with probability LOSS_PERCENT / 100 (seeded). The
devices go away when this process ends (SIGTERM/SIGINT end it cleanly). Prints "ready" on stdout
once both devices exist, and counts on exit.

Faults (scripts/faults.sh): each frame's delay is DELAY_MS +- J (uniform), a frame is sent twice
with probability P % (--dup), and with probability P % (--reorder) it skips the delay (it then
overtakes the frames before it, as netem's reorder does). --one-way shapes only frames coming out
of B (the namespace's side): A -> B frames pass at once. SIGUSR1 cuts the link (every frame
dropped: a partition) and SIGUSR2 restores it; SIGHUP turns the shaping off for good (a clean link
from then on: the faults have stopped).
"""
import fcntl
import heapq
import os
import random
import select
import signal
import struct
import subprocess
import sys
import time

TUNSETIFF = 0x400454CA
IFF_TAP = 0x0002
IFF_NO_PI = 0x1000


def open_tap(name):
    fd = os.open("/dev/net/tun", os.O_RDWR | os.O_NONBLOCK)
    fcntl.ioctl(fd, TUNSETIFF, struct.pack("16sH", name.encode(), IFF_TAP | IFF_NO_PI))
    return fd


def main():
    args = sys.argv[1:]
    opts = {"--jitter-ms": 0.0, "--dup": 0.0, "--reorder": 0.0}
    one_way = "--one-way" in args
    args = [x for x in args if x != "--one-way"]
    for name in list(opts):
        if name in args:
            i = args.index(name)
            try:
                opts[name] = float(args[i + 1])
            except (IndexError, ValueError):
                print("linkshaper: %s needs a number" % name, file=sys.stderr)
                return 2
            del args[i:i + 2]
    if len(args) not in (5, 6):
        print(__doc__, file=sys.stderr)
        return 2
    a_name, b_name, b_netns = args[0:3]
    delay_s = float(args[3]) / 1000.0
    loss = float(args[4]) / 100.0
    rng = random.Random(int(args[5]) if len(args) == 6 else 1)
    jitter_s = opts["--jitter-ms"] / 1000.0
    dup = opts["--dup"] / 100.0
    reorder = opts["--reorder"] / 100.0
    if not (0 <= jitter_s <= delay_s and 0 <= dup <= 1 and 0 <= reorder <= 1):
        print("linkshaper: jitter must be 0 to the delay, dup and reorder 0-100 %", file=sys.stderr)
        return 2
    if not (0 <= delay_s <= 10 and 0 <= loss <= 1):
        print("linkshaper: delay must be 0-10000 ms and loss 0-100 %", file=sys.stderr)
        return 2
    a = open_tap(a_name)
    b = open_tap(b_name)
    subprocess.run(["ip", "link", "set", b_name, "netns", b_netns], check=True)
    peer = {a: b, b: a}
    queue = []  # (due, seq, out_fd, frame)
    seq = 0
    counts = {"forwarded": 0, "lost": 0, "failed": 0, "duplicated": 0, "reordered": 0, "cut": 0}
    running = [True]
    state = {"cut": False, "clean": False}

    def stop(*_):
        running[0] = False

    def cut(*_):
        state["cut"] = True

    def mend(*_):
        state["cut"] = False

    def clean(*_):
        state["clean"] = True

    signal.signal(signal.SIGTERM, stop)
    signal.signal(signal.SIGINT, stop)
    signal.signal(signal.SIGUSR1, cut)
    signal.signal(signal.SIGUSR2, mend)
    signal.signal(signal.SIGHUP, clean)
    print("ready", flush=True)
    while running[0]:
        now = time.monotonic()
        while queue and queue[0][0] <= now:
            _, _, out, frame = heapq.heappop(queue)
            try:
                os.write(out, frame)
                counts["forwarded"] += 1
            except OSError:  # the device is down (not yet up, or being removed)
                counts["failed"] += 1
        timeout = max(0.0, queue[0][0] - now) if queue else 0.5
        try:
            ready, _, _ = select.select([a, b], [], [], timeout)
        except InterruptedError:
            continue
        for fd in ready:
            for _ in range(256):
                try:
                    frame = os.read(fd, 65536)
                except (BlockingIOError, OSError):
                    break
                if state["cut"]:
                    counts["cut"] += 1
                    continue
                now = time.monotonic()
                if state["clean"] or (one_way and fd == a):
                    seq += 1
                    heapq.heappush(queue, (now, seq, peer[fd], frame))
                    continue
                if rng.random() < loss:
                    counts["lost"] += 1
                    continue
                copies = 2 if rng.random() < dup else 1
                counts["duplicated"] += copies - 1
                for _ in range(copies):
                    if rng.random() < reorder:
                        due = now
                        counts["reordered"] += 1
                    else:
                        due = now + delay_s + rng.uniform(-jitter_s, jitter_s)
                    seq += 1
                    heapq.heappush(queue, (due, seq, peer[fd], frame))
    print("linkshaper %s<->%s: forwarded %d, lost %d, duplicated %d, reordered %d, cut %d, write failed %d"
          % (a_name, b_name, counts["forwarded"], counts["lost"], counts["duplicated"], counts["reordered"],
             counts["cut"], counts["failed"]), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""A site link shaped in user space, for kernels without sch_netem (scripts/multisite.sh).

    linkshaper.py A B B_NETNS DELAY_MS LOSS_PERCENT [SEED]

Creates two TAP devices A and B in the current network namespace, moves B into the namespace
B_NETNS (the open file keeps it attached), and forwards every Ethernet frame between them after
DELAY_MS milliseconds, dropping each frame with probability LOSS_PERCENT / 100 (seeded). The
devices go away when this process ends (SIGTERM/SIGINT end it cleanly). Prints "ready" on stdout
once both devices exist, and counts on exit.
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
    if len(sys.argv) not in (6, 7):
        print(__doc__, file=sys.stderr)
        return 2
    a_name, b_name, b_netns = sys.argv[1:4]
    delay_s = float(sys.argv[4]) / 1000.0
    loss = float(sys.argv[5]) / 100.0
    rng = random.Random(int(sys.argv[6]) if len(sys.argv) == 7 else 1)
    if not (0 <= delay_s <= 10 and 0 <= loss <= 1):
        print("linkshaper: delay must be 0-10000 ms and loss 0-100 %", file=sys.stderr)
        return 2
    a = open_tap(a_name)
    b = open_tap(b_name)
    subprocess.run(["ip", "link", "set", b_name, "netns", b_netns], check=True)
    peer = {a: b, b: a}
    queue = []  # (due, seq, out_fd, frame)
    seq = 0
    counts = {"forwarded": 0, "lost": 0, "failed": 0}
    running = [True]

    def stop(*_):
        running[0] = False

    signal.signal(signal.SIGTERM, stop)
    signal.signal(signal.SIGINT, stop)
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
                if rng.random() < loss:
                    counts["lost"] += 1
                    continue
                seq += 1
                heapq.heappush(queue, (time.monotonic() + delay_s, seq, peer[fd], frame))
    print("linkshaper %s<->%s: forwarded %d, lost %d, write failed %d"
          % (a_name, b_name, counts["forwarded"], counts["lost"], counts["failed"]), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/python3
"""An external command that fails as a program (argv[1]): `crash` answers two requests right
(through `zdg serve floor-sum`, argv[2] is zdg) and then dies of SIGSEGV, `exit` exits with
status 3, `hang` stops answering, `garbage` answers a line that is not JSON, `endless` answers
a line that never ends (a reader that waits for its end never sees a silent pipe)."""
import fcntl
import json
import os
import signal
import subprocess
import sys
import time

mode, zdg = sys.argv[1], sys.argv[2]
serve = subprocess.Popen([zdg, "serve", "floor-sum"], stdin=subprocess.PIPE,
                         stdout=subprocess.PIPE, text=True)
count = 0
for line in sys.stdin:
    count += 1
    if count == 3:
        if mode == "crash":
            os.kill(os.getpid(), signal.SIGSEGV)
        if mode == "exit":
            sys.exit(3)
        if mode == "hang":
            time.sleep(3600)
        if mode == "endless":
            # A 1 MiB pipe kept full at up to 64 MB/s: a reader that rescans its whole buffer
            # after each read falls behind within a fraction of a second and from then on finds
            # bytes waiting whenever it looks (it reads at most 64 KiB at a time), so only a
            # deadline on the whole answer ends the wait; within a timeout of a second the line
            # stays far below zdg's 256 MiB line limit.
            try:
                fcntl.fcntl(1, fcntl.F_SETPIPE_SZ, 1 << 20)
            except OSError:
                pass
            chunk, sent, start = b"7" * (1 << 16), 0, time.monotonic()
            while True:
                os.write(1, chunk)  # blocks while the pipe is full
                sent += len(chunk)
                ahead = sent / 64e6 - (time.monotonic() - start)
                if ahead > 0.005:
                    time.sleep(ahead)
        if mode == "garbage":
            print("value = 42", flush=True)
            continue
    serve.stdin.write(line)
    serve.stdin.flush()
    print(serve.stdout.readline(), end="", flush=True)

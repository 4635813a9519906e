#!/usr/bin/python3
"""An external command that fails as a program (argv[1]): `crash` answers two requests right
(through `zdg serve floor-sum`, argv[2] is zdg) and then dies of SIGSEGV, `exit` exits with
status 3, `hang` stops answering, `garbage` answers a line that is not JSON, `endless` answers
a line that never ends (1 MiB every 10 ms, about 100 MB/s: a reader that waits for its end never
sees a silent pipe)."""
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
            chunk = b"7" * (1 << 20)
            while True:
                sys.stdout.buffer.write(chunk)
                sys.stdout.buffer.flush()
                time.sleep(0.01)
        if mode == "garbage":
            print("value = 42", flush=True)
            continue
    serve.stdin.write(line)
    serve.stdin.flush()
    print(serve.stdout.readline(), end="", flush=True)

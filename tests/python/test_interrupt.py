"""Long calls release the GIL and stop on Ctrl-C: a KeyboardInterrupt reaches the caller within
about 0.2 s of SIGINT."""
import signal
import subprocess
import sys
import textwrap
import time

import samplescope

CHILD = textwrap.dedent(
    """
    import sys, time, samplescope
    print("start", flush=True)
    try:
        samplescope.points("best-candidate", 1000000, seed=1, m=10, budget=1e9)
        print("finished", flush=True)
    except KeyboardInterrupt:
        print("interrupted %.6f" % time.time(), flush=True)
    """
)


def test_ctrl_c_raises_keyboard_interrupt_promptly():
    child = subprocess.Popen([sys.executable, "-c", CHILD], stdout=subprocess.PIPE, text=True)
    assert child.stdout.readline().strip() == "start"
    time.sleep(1.0)
    sent = time.time()
    child.send_signal(signal.SIGINT)
    out, _ = child.communicate(timeout=30)
    assert child.returncode == 0
    word, at = out.split()
    assert word == "interrupted"
    assert float(at) - sent < 0.2 + 0.05  # 0.2 s, with slack for the print

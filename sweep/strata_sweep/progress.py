"""The progress line both backends print: runs done, failed, elapsed and ETA."""
import sys
import time


class Progress:
    def __init__(self, label, total, stream=sys.stderr):
        self.label, self.total, self.stream = label, total, stream
        self.start = time.monotonic()
        self.terminal = stream.isatty()

    def update(self, done, failed, final=False, extra=""):
        elapsed = time.monotonic() - self.start
        eta = elapsed / done * (self.total - done) if done else float("nan")
        eta_text = f"ETA {eta / 60:.1f} min" if done else "ETA unknown"
        line = (f"{self.label}: {done}/{self.total} runs, {failed} failed, {elapsed / 60:.1f} min elapsed, "
                f"{eta_text}{extra}")
        if self.terminal and not final:
            print("\r" + line + "   ", end="", file=self.stream, flush=True)
        else:
            print(("\r" if self.terminal else "") + line, file=self.stream, flush=True)

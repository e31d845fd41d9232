"""Files the scripts write appear whole or not at all, as roughgas's own outputs do: each is
written under a temporary name in its own directory and then renamed over the target (os.replace),
so an interrupted script never leaves a half-written picture or table."""
import os


def save_figure(fig, path, dpi=110):
    """A matplotlib figure as PNG at `path`."""
    tmp = path + ".tmp.png"
    fig.savefig(tmp, dpi=dpi, format="png")
    os.replace(tmp, path)


def write_text(path, text):
    """`text` to `path`."""
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, path)

"""Saving a figure of the plot scripts: written as `.NAME.tmp.png` and renamed when complete, so that an
interrupted script (agglo ends it on Ctrl-C or SIGTERM and removes `.*.tmp.png`) never leaves a
truncated PNG (apps/agglo/command.cpp, run_plot_script)."""
import os


def save(fig, folder, name, dpi):
    tmp = os.path.join(folder, "." + name[: -len(".png")] + ".tmp.png")
    fig.savefig(tmp, dpi=dpi)
    os.replace(tmp, os.path.join(folder, name))

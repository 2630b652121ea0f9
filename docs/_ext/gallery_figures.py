"""sphinx-gallery image scraper for matplotlib Figures that live outside pyplot.

jointwear's plotting functions return :class:`matplotlib.figure.Figure` objects
built without pyplot, so the gallery's default matplotlib scraper (which asks
pyplot for its open figures) sees none. This scraper picks up every Figure bound
to a name in the example's namespace after each code block, once.
"""

from __future__ import annotations

from matplotlib.figure import Figure
from sphinx_gallery.scrapers import figure_rst


def scraper(block, block_vars, gallery_conf, **kwargs):
    """Save the Figures an example block made; return the rST that shows them."""
    shown = block_vars.setdefault("jointwear_figures_shown", [])
    paths = []
    for value in list(block_vars["example_globals"].values()):
        if isinstance(value, Figure) and not any(value is seen for seen in shown):
            shown.append(value)
            path = next(block_vars["image_path_iterator"])
            value.savefig(path, dpi=96, bbox_inches="tight")
            paths.append(path)
    return figure_rst(paths, gallery_conf["src_dir"])


class ExampleOrder:
    """Gallery order: the quick start first, then the others by file name."""

    FIRST = ("quickstart.py", "contact_models.py")

    def __init__(self, src_dir: str) -> None:
        self.src_dir = src_dir

    def __call__(self, filename: str) -> tuple[int, str]:
        rank = self.FIRST.index(filename) if filename in self.FIRST else len(self.FIRST)
        return rank, filename

    def __repr__(self) -> str:  # sphinx-gallery compares configs by repr
        return f"{type(self).__name__}()"

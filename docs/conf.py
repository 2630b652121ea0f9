"""Sphinx configuration of the jointwear documentation.

Build: ``pip install -e ".[docs]"`` then ``python -m sphinx -W -b html docs DIR``.
"""

from __future__ import annotations

import shutil
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE / "_ext"))
# the API pages are generated from the code on every build; stale ones (of a renamed
# or removed name) would otherwise linger and warn
shutil.rmtree(HERE / "api" / "generated", ignore_errors=True)

from jointwear import __version__  # noqa: E402

project = "jointwear"
author = "the jointwear developers"
copyright = "the jointwear developers"
release = __version__
version = __version__

extensions = [
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "sphinx.ext.mathjax",
    "numpydoc",
    "myst_parser",
    "sphinx_gallery.gen_gallery",
]

source_suffix = {".rst": "restructuredtext", ".md": "markdown"}
root_doc = "index"
exclude_patterns = ["_build", "**/GALLERY_HEADER.rst", "sg_execution_times.rst"]
templates_path = ["_templates"]

# -- API reference: one page per public name of every module's __all__
autosummary_generate = True
autosummary_ignore_module_all = False
autosummary_imported_members = False
autodoc_default_options = {"member-order": "bysource"}
autodoc_typehints = "none"  # types are in the numpydoc text, with units
numpydoc_show_class_members = False
numpydoc_class_members_toctree = False
numpydoc_xref_param_type = False

# -- Markdown pages (README-style links between .md files resolve as documents)
myst_heading_anchors = 3
myst_enable_extensions = ["dollarmath"]

# -- gallery: the examples/ scripts, executed; figures are matplotlib Figure objects
sphinx_gallery_conf = {
    "examples_dirs": ["../examples"],
    "gallery_dirs": ["auto_examples"],
    "filename_pattern": r"\.py$",
    "ignore_pattern": r"__init__\.py",
    "image_scrapers": ("gallery_figures.scraper",),
    "download_all_examples": False,
    "remove_config_comments": True,
    "within_subsection_order": "gallery_figures.ExampleOrder",
    "min_reported_time": 10,
    "write_computation_times": False,
}

html_theme = "pydata_sphinx_theme"
html_title = f"jointwear {release}"
html_theme_options = {
    "navigation_with_keys": False,
    "show_toc_level": 2,
}
html_show_sourcelink = False

"""``python -m jointwear``."""

from jointwear.cli import main

main()

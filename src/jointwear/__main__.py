"""``python -m jointwear``."""

from __future__ import annotations

from jointwear.cli import main

if __name__ == "__main__":
    main()

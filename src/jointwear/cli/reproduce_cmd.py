"""``jointwear reproduce``: the paper's tables and figures, with a report."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from jointwear.cli.common import JsonOpt, SetOpt, app, console, emit_json
from jointwear.cli.progress import ProgressBar


@app.command()
def reproduce(
    out: Annotated[
        Path, typer.Option("--out", help="Folder for report.md, figures/ and results/.")
    ] = Path("reproduction"),
    case: Annotated[
        list[str] | None, typer.Option("--case", help="Run only these paper cases (repeatable).")
    ] = None,
    calibrate: Annotated[
        bool,
        typer.Option(
            "--calibrate/--no-calibrate",
            help="Calibrate the undisclosed parameters on Table 3, Winkler, 120 rpm first.",
        ),
    ] = True,
    set_: SetOpt = None,
    json_: JsonOpt = False,
    quiet: Annotated[bool, typer.Option("--quiet", "-q")] = False,
) -> None:
    """Run the paper's cases (Tables 3-5, Figs. 8-15) and write OUT/report.md."""
    from jointwear.paper.reproduce import reproduce_to_folder

    # a bar on a terminal, erased at the end: an error stays the only line on stderr
    with ProgressBar("paper cases", quiet=quiet or json_, delay=0.0) as bar:
        report, out = reproduce_to_folder(
            out,
            cases=case,
            calibrate=calibrate,
            overrides=set_ or [],
            progress=lambda name, done, total: bar(done, total),
        )
    if json_:
        emit_json(report)
        return
    holds = sum(t["holds"] for t in report["trends"])
    compiled = report["compile_s"]
    console.print(
        f"report: {out / 'report.md'}  ({len(report['cases'])} cases, "
        f"trends holding {holds}/{len(report['trends'])}, "
        f"{report['total_runtime_s']:.1f} s"
        + ("" if compiled is None else f", of which {compiled:.1f} s one-time compile")
        + ")"
    )

"""Workflows: what each command does, as library functions (runs, studies, their files).

==============================================  ===========================================
:mod:`jointwear.workflows.run`                  a run to a folder (``run``, ``plot``):
                                                checkpoints, resume, files, plots, summary
:mod:`jointwear.workflows.sweep`                parameter sweeps (``sweep``): the plan, its
                                                cases here, on local processes or on dask,
                                                their outputs
:mod:`jointwear.workflows.life`                 life with uncertainty (``life``): Monte Carlo
                                                on the sweep machinery, Kaplan-Meier
:mod:`jointwear.workflows.reliability`          B10/B50 lives with bounds, the Weibull fit
                                                of censored lives, each limit's probability
:mod:`jointwear.workflows.sensitivity`          Sobol indices and Morris screening
                                                (``sensitivity``) on the sweep machinery
:mod:`jointwear.workflows.calibration`          parameters fitted to measured bushings or to
                                                a contact reference (``calibrate``)
:mod:`jointwear.workflows.parameter_fit`        the least-squares fit of config parameters
                                                every calibration uses
:mod:`jointwear.workflows.measured`             a measured bushing's wear (``measure``), a
                                                run against it (``compare``)
:mod:`jointwear.workflows.contact_models`       one load on the unworn bushing
                                                (``contact``), every contact model against a
                                                reference (``compare-models``)
:mod:`jointwear.workflows.dynamics`             the load cycle of each joint, its CSV files
                                                (``dynamics``)
:mod:`jointwear.workflows.inputs`               config files and option texts with units
==============================================  ===========================================

The command line (:mod:`jointwear.cli`) parses the options, calls one function of
these modules and prints what it returns; the paper's row calibration
(``calibrate --paper-row``) is :func:`jointwear.paper.protocol.paper_row_calibration` and
``reproduce`` is :func:`jointwear.paper.reproduce.reproduce_to_folder`.
Nothing is imported here: ``import jointwear.workflows.run`` loads what a run needs,
and no more.
"""

"""Workflows: what a command does, as library functions (many runs, files, studies).

=========================================  ================================================
:mod:`jointwear.workflows.sweep`           parameter sweeps: the plan, its cases run
                                           serially, on local processes or on dask, and
                                           their outputs (``cases.csv``, ``sweep.nc``)
:mod:`jointwear.workflows.life`            life with uncertainty (Monte Carlo on the
                                           sweep machinery, Kaplan-Meier quantiles)
:mod:`jointwear.workflows.parameter_fit`   least-squares fit of config parameters to
                                           observed wear
=========================================  ================================================

The command line (:mod:`jointwear.cli`) parses options, calls one function of these
modules and prints what it returns. Nothing is imported here: ``import
jointwear.workflows.life`` loads what the life study needs, and no more.
"""

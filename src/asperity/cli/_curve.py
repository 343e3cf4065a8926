"""What ``asperity load`` and ``asperity separation`` share: lists, the model or contact, output.

A curve command takes its points either dimensionless (``--P``, ``--d``, with
``--alpha``/``--beta``) or physical (``--load``, ``--separation``, with units and a
physical contact), asks the library for the curve, and writes it (and ``--plot``).
"""

from __future__ import annotations

from ._args import UsageError, parse_list, quantity_list
from ._build import contact_from_args, is_physical, model_from_args, title
from ._output import curve_rows, format_physical, format_rows, output_format, write_outputs

__all__ = ["run_curve"]

#: kind -> (dimensionless option, physical option, SI unit, log-spaced ranges)
KINDS = {
    "separation": ("d", "separation", "m", False),
    "load": ("P", "load", "N", True),
}


def run_curve(args, kind: str) -> None:
    """Compute the ``kind`` curve (``'load'`` or ``'separation'``) of ``args`` and write it.

    A physical result starts with the contact computed; a real contact area above 10 % of
    the nominal area is the library's :class:`~asperity.AreaFractionWarning`, which the
    command line prints as one note.
    """
    dimless_opt, phys_opt, unit, log = KINDS[kind]
    physical = is_physical(args)
    names = (f"--{dimless_opt}", f"--{phys_opt}")
    dimless, phys = getattr(args, dimless_opt), getattr(args, phys_opt)
    text = phys if physical else dimless
    if text is None or (phys if not physical else dimless) is not None:
        want, other = (names[1], names[0]) if physical else names
        raise UsageError(f"give {want} LIST" + (f" (not {other}) with a physical contact" if physical
                                               else f" (or a physical contact, --material ..., with {names[1]})"))
    contact = None
    if physical:
        values = quantity_list(text, unit, log=log, name=names[1])
        contact = contact_from_args(args)
        curve = getattr(contact, f"{kind}_curve")(values)
    else:
        values = parse_list(text, log=log, name=names[0])
        curve = getattr(model_from_args(args), f"{kind}_curve")(values)

    def plot(path, fmt):
        from ._plot import plot_curve

        plot_curve(curve, path, fmt, x="d" if kind == "separation" else "P", title=title(args, contact),
                   physical=physical)

    fmt = output_format(args)
    rows = curve_rows(curve)
    text = format_physical(rows, fmt, contact, comments=not args.no_comments) if physical else format_rows(rows, fmt)
    write_outputs(text, args, plot=plot)

"""The paper's Figs 3-9: one entry per figure with its data, drawing and checks.

Each figure is a :class:`FigureSpec`; ``spec.data()`` computes the curves
(:class:`~asperity.studies._common.FigureData`), ``spec.draw(data)`` returns a matplotlib
Figure (Agg canvas, 6 x 4.5 in; matplotlib is imported only then) and
``spec.checks(data)`` returns the paper's claims about the figure, each a
``(claim, passed, detail)`` :class:`~asperity.studies._common.Check`.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

from . import friction, pressure, separation
from ._common import Check, FigureData

__all__ = ["FigureSpec", "FIGURES"]


@dataclass(frozen=True)
class FigureSpec:
    number: int
    short: str  #: one line for progress messages
    data: Callable[[], FigureData]
    draw: Callable[[FigureData], object]
    checks: Callable[[FigureData], list[Check]]

    @property
    def name(self) -> str:
        return f"fig{self.number}"


FIGURES: dict[int, FigureSpec] = {
    spec.number: spec for spec in (
        FigureSpec(3, "alpha*mu vs P/alpha, no adhesion, beta = 1e2..1e6",
                   friction.fig3_data, friction.fig3_draw, friction.fig3_checks),
        FigureSpec(4, "alpha*mu vs P/alpha with adhesion, several alpha",
                   friction.fig4_data, friction.fig4_draw, friction.fig4_checks),
        FigureSpec(5, "alpha*mu vs P/alpha, several beta, with and without adhesion",
                   friction.fig5_data, friction.fig5_draw, friction.fig5_checks),
        FigureSpec(6, "mu vs P, several gamma",
                   friction.fig6_data, friction.fig6_draw, friction.fig6_checks),
        FigureSpec(7, "normal force vs d/sigma",
                   separation.fig7_data, separation.fig7_draw, separation.fig7_checks),
        FigureSpec(8, "friction force vs d/sigma",
                   separation.fig8_data, separation.fig8_draw, separation.fig8_checks),
        FigureSpec(9, "P/(E* A) vs P, with and without adhesion",
                   pressure.fig9_data, pressure.fig9_draw, pressure.fig9_checks),
    )
}

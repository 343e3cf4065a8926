r"""Interacting and coalescing Hertzian asperities (ICHA) on the summits of a measured map.

The Greenwood-Williamson model treats a rough surface as a *statistical* population of
independent Hertzian caps.  The ICHA model of Afferrante, Carbone & Demelio (2012) keeps
the caps Hertzian but makes the model *deterministic* and *coupled*:

* **the asperities are the summits of the map itself** (:func:`map_summits`): each with its
  own height, principal curvatures and position, no distribution;
* **interaction**: every contact spot presses the surface in by the Hertzian displacement
  field of its force (:func:`~asperity.icha.field.hertz_displacement`, Johnson Eq 3.42),
  which lowers every other asperity; on a periodic map all images count
  (:class:`~asperity.icha.field.PeriodicKernel`, Ewald's sum of the same periodic Green's
  function as the boundary elements);
* **coalescence**: two spots whose contact circles overlap become one equivalent Hertzian
  spot with the sum of their areas and forces (:func:`~asperity.icha.solver.merge_spots`),
  which grows from then on with the larger radius this implies.

Under load control the flat's position and the forces are solved together (active-set
Newton), load after load from the previous state (:func:`icha_contact`, :func:`icha_curve`).
With ``interaction=False, coalescence=False`` it is the plain Hertz sum over the summits.

Assumptions: frictionless, non-adhesive, linear elastic half-space (small slopes);
paraboloidal caps (Hertz) on the summits of the grid, with the radius of the sphere
equivalent to each cap's elliptical contact (or the mean-curvature radius); interaction
through the Hertz field of each spot (the real pressure of a spot next to others is not
Hertzian); coalescence irreversible along increasing load.

Sources: the model as summarised in the abstract of Afferrante, Bottiglione, Putignano,
Persson & Carbone (2018); the 2012 paper itself could not be consulted here, so the details
(equivalent spot conserving area *and* force at the area-weighted centroid, radius of the
equivalent sphere) are our reading and are stated where used (docs/validation.md).

References
----------
.. [1] L. Afferrante, G. Carbone, G. Demelio, Interacting and coalescing Hertzian asperities:
   a new multiasperity contact model, Wear 278-279 (2012) 28-33.
.. [2] L. Afferrante, F. Bottiglione, C. Putignano, B. N. J. Persson, G. Carbone, Elastic
   contact mechanics of randomly rough surfaces: an assessment of advanced asperity models
   and Persson's theory, Tribol. Lett. 66 (2018) 75.
.. [3] K. L. Johnson, *Contact Mechanics*, Cambridge University Press (1985), §3.4, §4.2.
"""

from .contact import MAX_LOADS, MAX_SUMMITS, P_BAR_RANGE, IchaCurve, icha_contact, icha_curve
from .field import FreeKernel, PeriodicKernel, hertz_displacement, hertz_excess
from .rectangle import boussinesq_rectangle_mean
from .solver import IchaState, merge_spots
from .summits import RADII, MapSummits, map_summits

__all__ = [
    "IchaCurve",
    "icha_contact",
    "icha_curve",
    "MapSummits",
    "map_summits",
    "RADII",
    "merge_spots",
    "IchaState",
    "hertz_displacement",
    "hertz_excess",
    "boussinesq_rectangle_mean",
    "FreeKernel",
    "PeriodicKernel",
    "MAX_SUMMITS",
    "MAX_LOADS",
    "P_BAR_RANGE",
]

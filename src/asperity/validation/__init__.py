r"""Check the models against a full elastic boundary-element contact of the same surface.

The Greenwood-Williamson model treats asperities as independent Hertzian caps with
Gaussian heights and one radius; a measured surface is neither.  This package solves the
full elastic contact of the same surface (boundary elements, ContactMechanics, optional
extra ``bem``) and puts it beside the models for the same material and loads (GW; the
interacting and coalescing Hertzian asperities of :mod:`asperity.icha`; Persson's area and
the BGT asymptote of :mod:`asperity.persson`): real contact area, mean gap and number of
contact spots, with the deviation.

=============================================  ==================================================
module                                         contents
=============================================  ==================================================
:mod:`~asperity.validation.bem`                :func:`bem_contact`, :class:`BemCurve`, :func:`subsample`
:mod:`~asperity.validation.spots`              :func:`count_spots`, :func:`label_spots` (periodic-aware)
:mod:`~asperity.validation.compare`            :func:`validate_surface`, :class:`SurfaceValidation`
:mod:`~asperity.validation.models`             :data:`MODELS`, the columns and runs of each model
:mod:`~asperity.validation.plot`               :func:`plot_validation` (matplotlib)
:mod:`~asperity.validation.progress`           :func:`progress_bar` (tqdm, else plain lines)
=============================================  ==================================================

Adhesion is not included: ContactMechanics solves hard-wall (non-adhesive) contact; the
Adhesion package declares a Dugdale interaction but no solver uses it (docs/validation.md).

``pip install 'asperity[bem]'`` (ContactMechanics, which brings SurfaceTopography).
"""

from .bem import DEFAULT_TOLERANCE, MAX_LOADS, MIN_GRID, BemCurve, bem_contact, subsample
from .compare import METHODS, SurfaceValidation, validate_surface
from .models import MODELS
from .progress import progress_bar
from .spots import count_spots, label_spots

__all__ = [
    "BemCurve",
    "bem_contact",
    "subsample",
    "count_spots",
    "label_spots",
    "SurfaceValidation",
    "validate_surface",
    "progress_bar",
    "METHODS",
    "MODELS",
    "MIN_GRID",
    "MAX_LOADS",
    "DEFAULT_TOLERANCE",
]

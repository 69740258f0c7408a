"""LMGC90's chipy on lmgc: the functions LMGC90's command.py scripts call, with LMGC90's names,
argument names, defaults and meaning (pylmgc90/chipy/macro.py and the RBDY2/RBDY3 wrappers of
LMGC90 2025), run by lmgc's solver through lmgc._chipy.

What lmgc does not do raises NotImplementedError naming the call; calls out of order, unknown
bodies and wrong arguments raise RuntimeError, IndexError or ValueError. docs/chipy.md lists every
call and what it does here.
"""
import os
import sys
import time as _time

import numpy as _np

from lmgc import _chipy

__all__ = []  # filled below: every function LMGC90 scripts may import with `from ... import *`

_session = None
_log_messages = True
_run_options = {"max_steps": -1, "quiet": False}
_timers = []
_INTERACTION_NAMES = {}  # interaction module name -> LMGC90's id (DKDKx_ID, ...)


def _export(function):
    __all__.append(function.__name__)
    return function


def _configure(max_steps=-1, quiet=False):
    """lmgc-run's options: end the script after max_steps steps (.LAST written); no warnings."""
    _run_options["max_steps"] = int(max_steps)
    _run_options["quiet"] = bool(quiet)


def _s():
    if _session is None:
        raise RuntimeError("chipy: Initialize() first")
    return _session


# --- set-up ----------------------------------------------------------------------------------


@_export
def Initialize():
    """Start a session in the current directory (the case folder)."""
    global _session, _timers
    if _session is not None:
        _session.finalize()
    _session = _chipy.Session(os.getcwd(), _run_options["max_steps"], _run_options["quiet"])
    _timers = []


@_export
def Finalize():
    """Close the output files and print the run's summary (convergence, worst residual)."""
    if "--no-finalize" in sys.argv or _session is None:
        return
    _session.finalize()


@_export
def checkDirectories(checkDATBOX=True):
    """Stop when DATBOX/ is missing; create OUTBOX/, POSTPRO/ and DISPLAY/."""
    if checkDATBOX and not os.path.isdir("DATBOX"):
        raise RuntimeError("checkDirectories: no DATBOX directory in " + os.getcwd())
    for folder in ("OUTBOX", "POSTPRO", "DISPLAY"):
        os.makedirs(folder, exist_ok=True)


@_export
def SetDimension(dim, mod=1):
    _s().set_dimension(int(dim), int(mod))


@_export
def GetDimension():
    return _s().dimension()


@_export
def TimeEvolution_SetTimeStep(value):
    _s().set_time_step(float(value))


@_export
def TimeEvolution_GetTimeStep():
    return _s().time_step()


@_export
def TimeEvolution_GetTime():
    return _s().time()


@_export
def TimeEvolution_GetStep():
    return _s().step()


@_export
def Integrator_InitTheta(value):
    _s().init_theta(float(value))


@_export
def nlgs_SetWithQuickScramble():
    _s().set_quick_scramble(2)


@_export
def nlgs_3D_SetWithQuickScramble():
    _s().set_quick_scramble(3)


@_export
def nlgs_3D_DiagonalResolution():
    _s().set_diagonal_resolution()


@_export
def SetPeriodicCondition(xperiod=None, yperiod=None):
    _s().set_periodic(None if xperiod is None else float(xperiod), None if yperiod is None else float(yperiod))


def _boundary(axis, maximum):
    def set_boundary(value):
        _s().set_boundary(axis, maximum, float(value))
    return set_boundary


for _axis in "XY":
    for _side, _maximum in (("min", False), ("max", True)):
        _name = "RBDY2_Set%s%sBoundary" % (_axis, _side)
        globals()[_name] = _boundary(_axis.lower(), _maximum)
        globals()[_name].__name__ = _name
        __all__.append(_name)


@_export
def RBDY3_NewRotationScheme():
    _s().new_rotation_scheme()


@_export
def RBDY3_SetSourcePoint(first_RBDY3, radius, Xshift, Yshift, Zshift):
    _s().set_source_point(int(first_RBDY3), float(radius), float(Xshift), float(Yshift), float(Zshift), False)


@_export
def RBDY3_SetSourcePointWithIni(first_RBDY3, radius, Xshift, Yshift, Zshift):
    _s().set_source_point(int(first_RBDY3), float(radius), float(Xshift), float(Yshift), float(Zshift), True)


@_export
def PRPRx_UseCpCundallDetection(nb_iter):
    _s().set_cundall_iterations(int(nb_iter))


@_export
def PRPRx_LowSizeArrayPolyr(sizefactor):
    """Sizes one of LMGC90's arrays: nothing to do in lmgc."""


@_export
def PTPT3_LoadNetwork():
    _s().ptpt3_load_network()


@_export
def PTPT3_UseCurrentNonuc0(to_use):
    _s().ptpt3_use_current_nonuc0(int(to_use))


# --- messages and timers (no effect on the run) ------------------------------------------------


@_export
def utilities_logMes(mes):
    if _log_messages:
        print(mes)


@_export
def utilities_EnableLogMes():
    global _log_messages
    _log_messages = True


@_export
def utilities_DisableLogMes():
    global _log_messages
    _log_messages = False


@_export
def timer_GetNewTimer(name):
    _timers.append([name, 0.0, None])
    return len(_timers)


@_export
def timer_StartTimer(timer_id):
    _timers[timer_id - 1][2] = _time.perf_counter()


@_export
def timer_StopTimer(timer_id):
    t = _timers[timer_id - 1]
    if t[2] is not None:
        t[1] += _time.perf_counter() - t[2]
        t[2] = None


@_export
def timer_InitializeTimers():
    pass


@_export
def timer_ClearAll():
    del _timers[:]


@_export
def timer_WriteOutTimers():
    pass


@_export
def PRPRx_VerboseF2F(cd, an):
    """Prints LMGC90's face-to-face detection details: nothing to print in lmgc."""


# --- DATBOX --------------------------------------------------------------------------------------

_R = _chipy.Reading


@_export
def ReadBehaviours():
    _s().read(_R.behaviours)


@_export
def ReadBodies(version=None):
    _s().read(_R.bodies)


@_export
def LoadBehaviours():
    _s().read(_R.load_behaviours)


@_export
def ReadIniDof(record=0):
    if record:
        raise NotImplementedError("ReadIniDof(record=%d): lmgc reads DATBOX/DOF.INI only" % record)
    _s().read(_R.ini_dof)


@_export
def ReadDrivenDof():
    _s().read(_R.driven_dof)


@_export
def LoadTactors():
    _s().read(_R.tactors)


@_export
def ReadIniVlocRloc(record=0):
    if record:
        raise NotImplementedError("ReadIniVlocRloc(record=%d): lmgc reads DATBOX/Vloc_Rloc.INI only" % record)
    _s().read(_R.ini_vloc_rloc)


@_export
def ReadModels():
    """MODELS.DAT is read with the case (the first reading); deformable bodies run as linear elastic
    meshes (small strain, ELAS) without contact."""


@_export
def LoadModels():
    """Done with the case's reading."""


@_export
def ReadIniGPV(record=0):
    """GPV.INI holds no state lmgc needs for linear elasticity (stresses follow from the displacements)."""
    if record:
        raise NotImplementedError("ReadIniGPV(record=%d): lmgc reads DATBOX/GPV.INI only" % record)


@_export
def ReadIni(record=0, h5_file=''):
    if h5_file:
        raise NotImplementedError("ReadIni(h5_file=...): lmgc reads no HDF5 state")
    ReadIniDof(record)
    ReadIniGPV(record)
    ReadIniVlocRloc(record)


@_export
def WriteBodies(version=None):
    _s().write_echo("WriteBodies")


@_export
def WriteBehaviours():
    _s().write_echo("WriteBehaviours")


@_export
def models_WriteModels():
    _s().write_echo("WriteModels")


@_export
def WriteDrivenDof():
    _s().write_echo("WriteDrivenDof")


@_export
def ReadDatbox(deformable=True):
    """Read every DATBOX file (and check the case, as lmgc-check does), then write the echo files."""
    ReadBehaviours()
    if deformable:
        ReadModels()
    ReadBodies()
    LoadBehaviours()
    if deformable:
        LoadModels()
    ReadIniDof()
    if deformable:
        ReadIniGPV()
    ReadDrivenDof()
    LoadTactors()
    ReadIniVlocRloc()
    WriteBodies()
    WriteDrivenDof()
    WriteBehaviours()
    if deformable:
        models_WriteModels()


@_export
def ComputeMass():
    _s().compute_mass()


# --- the step ----------------------------------------------------------------------------------


def _stage(name):
    def run_stage():
        _s().stage(name)
    run_stage.__name__ = name
    run_stage.__doc__ = "The %s stage of the step." % name
    return run_stage


for _name in ("IncrementStep", "ComputeFext", "ComputeBulk", "ComputeFreeVelocity", "UpdateTactBehav",
              "StockRloc", "ComputeDof", "UpdateStep"):
    globals()[_name] = _stage(_name)
    __all__.append(_name)


@_export
def SelectProxTactors(freq_detec=1, useExt=0, reset=0):
    _s().select_prox_tactors(int(freq_detec), int(useExt), int(reset))


@_export
def RecupRloc(tol=None):
    _s().recup_rloc(None if tol is None else float(tol))


@_export
def ExSolver(stype, norm, conv, relax, gsit1, gsit2):
    _s().ex_solver(str(stype), str(norm), float(conv), float(relax), int(gsit1), int(gsit2))


# --- outputs -----------------------------------------------------------------------------------


@_export
def WriteOutDof(nsteps=1):
    _s().write_out_dof(int(nsteps))


@_export
def WriteOutVlocRloc(nsteps=1):
    _s().write_out_vloc_rloc(int(nsteps))


@_export
def WriteOutGPV(nsteps=1):
    _s().write_out_gpv(int(nsteps))


@_export
def WriteLastGPV():
    _s().write_last_gpv()


@_export
def WriteOut(nsteps=1):
    WriteOutDof(nsteps)
    if _s().has_deformable_bodies():
        WriteOutGPV(nsteps)
    # As LMGC90's WriteOut: Vloc_Rloc when TACT_BEHAV.DAT defines a law.
    if _s().has_contact_laws():
        WriteOutVlocRloc(nsteps)


@_export
def WriteLastDof():
    _s().write_last_dof()


@_export
def WriteLastVlocRloc():
    _s().write_last_vloc_rloc()


@_export
def WriteLast(filename=None):
    if filename is not None:
        raise NotImplementedError("WriteLast(filename): lmgc writes no HDF5 state")
    WriteLastDof()
    if _s().has_deformable_bodies():
        WriteLastGPV()
    if _s().has_contact_laws():
        WriteLastVlocRloc()


# --- deformable bodies (linear elastic meshes, without contact) ----------------------------------


@_export
def mecaMAILx_ComputeRayleighDamping(alpha, beta):
    """C = alpha M + beta K on every deformable body."""
    _s().set_rayleigh_damping(float(alpha), float(beta))


@_export
def mecaMAILx_SetPreconAllBodies():
    """LMGC90 condenses the iteration matrix on the contact nodes of the bodies asked; lmgc always
    condenses it on the nodes of every mesh contactor (and again each time the matrix changes)."""


@_export
def mecaMAILx_ComputePreconW():
    """See mecaMAILx_SetPreconAllBodies."""


@_export
def CLxxx_PushPreconNodes():
    """See mecaMAILx_SetPreconAllBodies."""


@_export
def ALpxx_PushPreconNodes():
    """See mecaMAILx_SetPreconAllBodies."""


@_export
def PT2DL_PushPreconNodes():
    """See mecaMAILx_SetPreconAllBodies."""


@_export
def DISKL_PushPreconNodes():
    """See mecaMAILx_SetPreconAllBodies."""


@_export
def AssembleMechanicalLHS():
    """lmgc assembles and factorises the iteration matrix M + θhC + (θh)²K itself in ComputeFreeVelocity:
    once while h and θ stay for a linear body, at every Newton iteration (from the tangent) for a
    large-strain one."""


@_export
def AssembleMechanicalRHS():
    """lmgc assembles the right-hand side inside ComputeFreeVelocity, from the iterate the call starts
    from (mecaMAILx_ComputeResidueNorm reads it)."""


# --- Newton-Raphson loop (LMGC90's mod_overall, for deformable bodies) ----------------------------


def _newton_setter(name):
    def set_parameter(value):
        _s().set_newton_parameter(name, float(value))
    set_parameter.__name__ = "NewtonRaphson_Set" + name
    set_parameter.__doc__ = "LMGC90's NewtonRaphson_Set%s." % name
    return _export(set_parameter)


for _name in ("FinalTime", "MinTimeStep", "MaxTimeStep", "MaxIter", "GoodIter", "BadIter", "IncPatience"):
    globals()["NewtonRaphson_Set" + _name] = _newton_setter(_name)


@_export
def NewtonRaphson_Initialize(tol):
    """The step's Newton loop starts: convergence when the residue norm is below tol."""
    _s().newton_initialize(float(tol))


@_export
def NewtonRaphson_CheckConvergence(norm):
    """0 converged, 1 iterate again, 2 diverged (the iteration limit reached)."""
    return _s().newton_check_convergence(float(norm))


@_export
def NewtonRaphson_ComputeTimeStep():
    """0 go on, 1 redo the step (with h/√2), 2 stop (the final time reached); the next step's h."""
    return _s().newton_compute_time_step()


@_export
def mecaMAILx_ComputeResidueNorm():
    """The largest over deformable bodies of |R + I_reac|_inf over the largest force impulse."""
    return _s().residue_norm()


@_export
def OpenDisplayFiles(restart=1, mecagp_field=None, thergp_field=None, write_f2f=0, write_parameters=True):
    if mecagp_field is not None or thergp_field is not None:
        raise NotImplementedError("OpenDisplayFiles: Gauss-point fields belong to deformable bodies")
    _s().open_display()


@_export
def WriteDisplayFiles(freq=1, ref_radius=None, normal_orient=None, write_gp=None, **kw):
    if write_gp:
        raise NotImplementedError("WriteDisplayFiles(write_gp=...): Gauss-point fields belong to deformable "
                                  "bodies")
    _s().write_display(int(freq))


@_export
def CloseDisplayFiles():
    _s().close_display()


@_export
def OpenPostproFiles(restart=0):
    if restart:
        raise NotImplementedError("OpenPostproFiles(restart=%d): lmgc starts the POSTPRO files afresh" % restart)
    _s().open_postpro()


@_export
def WritePostproFiles(force_flush=False):
    _s().write_postpro()


@_export
def ClosePostproFiles():
    _s().close_postpro()


# --- state ---------------------------------------------------------------------------------------


def _bodies(dimension):
    prefix = "RBDY%d_" % dimension

    def get_nb():
        return _s().body_count(dimension)

    def get_body_vector(cvalue1, ivalue1):
        return _s().body_vector(dimension, str(cvalue1), int(ivalue1))

    def get_all_body_vector(cvalue1):
        return _s().all_body_vectors(dimension, str(cvalue1))

    def put_body_vector(cvalue1, ivalue1, rvect):
        _s().put_body_vector(dimension, str(cvalue1), int(ivalue1), _np.asarray(rvect, dtype=float))

    def put_all_body_vector(cvalue1, rmat):
        rows = _np.asarray(rmat, dtype=float)
        if rows.ndim != 2 or rows.shape[0] != get_nb():
            raise ValueError("%sPutAllBodyVector: a matrix of %d rows, one per body" % (prefix, get_nb()))
        for i, row in enumerate(rows):
            put_body_vector(cvalue1, i + 1, row)

    def set_vlocy_driven_dof(ibdyty, idrvdof, value):
        _s().set_vlocy_driven_dof(dimension, int(ibdyty), int(idrvdof), float(value))

    def get_body_mass(ibdyty):
        return _s().body_mass(dimension, int(ibdyty))

    def get_all_mass():
        return _np.array([get_body_mass(i + 1) for i in range(get_nb())])

    def is_visible(ibdyty):
        return 1 if _s().body_visible(dimension, int(ibdyty)) else 0

    calls = {
        "GetNbRBDY%d" % dimension: get_nb,
        "GetBodyVector": get_body_vector,
        "GetAllBodyVector": get_all_body_vector,
        "PutBodyVector": put_body_vector,
        "PutAllBodyVector": put_all_body_vector,
        "SetVlocyDrivenDof": set_vlocy_driven_dof,
        "GetBodyMass" if dimension == 2 else "GetMass": get_body_mass,
        "GetAllMass": get_all_mass,
        "IsVisible": is_visible,
    }
    for suffix, function in calls.items():
        function.__name__ = prefix + suffix
        globals()[prefix + suffix] = function
        __all__.append(prefix + suffix)


_bodies(2)
_bodies(3)


@_export
def getInteractions(this=False, human=True):
    """The step's interactions as a numpy structured array with chipy's field names (inter, icdan,
    cdbdy, anbdy, icdbdy, ianbdy, cdtac, antac, icdtac, iantac, behav, status, coor, uc, rl, vl,
    gapTT): the records of Vloc_Rloc, in LMGC90's order; rl is the mean force r/h. human=False
    (LMGC90's integer ids for names) is not offered."""
    if not human:
        raise NotImplementedError("getInteractions(human=False): lmgc gives names, not LMGC90's integer ids")
    data = _s().interactions()
    d = _s().dimension()
    n = len(data["inter"])
    dtype = [("inter", "U5"), ("icdan", int), ("cdbdy", "U5"), ("anbdy", "U5"), ("icdbdy", int),
             ("ianbdy", int), ("cdtac", "U5"), ("antac", "U5"), ("icdtac", int), ("iantac", int),
             ("behav", "U5"), ("status", "U5"), ("coor", float, (d,)), ("uc", float, (d, d)),
             ("rl", float, (d,)), ("vl", float, (d,)), ("gapTT", float)]
    inters = _np.zeros(n, dtype=dtype)
    for field in ("inter", "icdan", "cdbdy", "anbdy", "icdbdy", "ianbdy", "cdtac", "antac", "icdtac",
                  "iantac", "behav", "status", "coor", "rl", "vl", "gapTT"):
        inters[field] = data[field]
    # uc's columns are the local frame's vectors (t, n[, s]), as in chipy.
    inters["uc"] = _np.transpose(data["uc"], (0, 2, 1))
    return inters


def _contactor_calls(kind):
    def get_nb():
        return len(_s().contactors(kind))

    def get_ptr():
        return _s().contactors(kind)

    for suffix, function in (("GetNb" + kind, get_nb), ("GetPtr%s2BDYTY" % kind, get_ptr)):
        function.__name__ = kind + "_" + suffix
        globals()[function.__name__] = function
        __all__.append(function.__name__)


for _kind in ("DISKx", "xKSID", "POLYG", "JONCx", "PT2Dx", "SPHER", "CYLND", "DNLYC", "POLYR", "PLANx", "PT3Dx"):
    _contactor_calls(_kind)


def _equilibrium(dimension):
    prefix = "RBDY%d_" % dimension
    norm = {"checktype": "Qvlcy", "tol": 0.0}

    def set_equilibrium_norm(checktype, tol):
        if checktype not in ("Qvlcy", "Mvlcy"):
            raise ValueError("%sSetEquilibriumNorm: checktype is 'Qvlcy' or 'Mvlcy', not %r" % (prefix, checktype))
        norm["checktype"], norm["tol"] = checktype, float(tol)

    def check_equilibrium_state():
        # mod_RBDY2/3 check_equilibrium_state: |V_begin| of every visible body, their sum over the
        # number of bodies ('Qvlcy') or their maximum ('Mvlcy') against the tolerance.
        n = _s().body_count(dimension)
        if n == 0:
            return False
        speeds = [float(_np.linalg.norm(_s().body_vector(dimension, "Vbeg_", i + 1))) for i in range(n)
                  if _s().body_visible(dimension, i + 1)]
        value = sum(speeds) / n if norm["checktype"] == "Qvlcy" else max(speeds, default=-1e20)
        return value <= norm["tol"]

    for suffix, function in (("SetEquilibriumNorm", set_equilibrium_norm),
                             ("CheckEquilibriumState", check_equilibrium_state)):
        function.__name__ = prefix + suffix
        globals()[function.__name__] = function
        __all__.append(function.__name__)


_equilibrium(2)
_equilibrium(3)


@_export
def RBDY2_ComputeMass():
    _s().compute_mass()


@_export
def RBDY3_ComputeMass():
    _s().compute_mass()


@_export
def TimeEvolution_DisplayStep():
    print("@ Step %d, time %g" % (TimeEvolution_GetStep(), TimeEvolution_GetTime()))


@_export
def PT2Dx_SetDisplayRadius(radius):
    """The radius PT2Dx points are drawn with: display only."""


@_export
def PT3Dx_SetDisplayRadius(radius):
    """The radius PT3Dx points are drawn with: display only."""


@_export
def checkInteractiveCommand(last_name='last.h5'):
    """LMGC90 polls a file of interactive commands here; lmgc has none to poll."""


# LMGC90's parameter ids (Initialize sets them in chipy): body models, contactors, interactions.
for _ids in (("RBDY2", "RBDY3", "MAILx", "MBS3D", "MBS2D"),
             ("DISKx", "xKSID", "POLYG", "JONCx", "PT2Dx", "SPHER", "CYLND", "DNLYC", "POLYR", "PLANx", "PT3Dx",
              "ALpxx", "CLxxx", "DISKL", "PT2DL", "ASpxx", "CSxxx"),
             ("DKDKx", "DKKDx", "DKPLx", "DKJCx", "DKALp", "DKDKL", "PLPLx", "PLJCx", "PLALp", "PTPT2", "P2P2L",
              "SPSPx", "SPCDx", "SPDCx", "SPPLx", "CDCDx", "CDPLx", "PRPRx", "PRPLx", "PRASp", "PTPT3", "CLALp",
              "CLJCx", "CSASp", "CSPRx", "SPPRx")):
    for _k, _name in enumerate(_ids):
        globals()[_name + "_ID"] = _k + 1
        __all__.append(_name + "_ID")
_INTERACTION_NAMES.update({name: globals()[name + "_ID"] for name in _ids})


def _inter_handler(dimension):
    prefix = "inter_handler_%dD_" % dimension

    def rows(inter_id):
        if _s().dimension() != dimension:
            raise RuntimeError("%s in a %dD case" % (prefix.rstrip("_"), _s().dimension()))
        data = _s().interactions()
        return data, [k for k, name in enumerate(data["inter"]) if _INTERACTION_NAMES.get(name) == int(inter_id)]

    def get_nb(inter_id):
        return len(rows(inter_id)[1])

    def get_all(inter_id):
        # chipy's real data per interaction: coor, the local frame (t, n[, s]), rl (r/h), vl, gap.
        data, keep = rows(inter_id)
        d = dimension
        columns = [data["coor"][keep]] + [data["uc"][keep][:, k, :] for k in range(d)] + \
                  [data["rl"][keep], data["vl"][keep], data["gapTT"][keep][:, None]]
        return _np.hstack(columns) if keep else _np.zeros((0, d * (d + 3) + 1))

    for suffix, function in (("getNb", get_nb), ("getAll", get_all)):
        function.__name__ = prefix + suffix
        globals()[function.__name__] = function
        __all__.append(function.__name__)


_inter_handler(2)
_inter_handler(3)


# --- what lmgc does not offer -------------------------------------------------------------------

_SUPPORT_NOT_RUN = {5: "is not done by lmgc", 6: "is LMGC90's multi-physics, which lmgc does not run",
                    7: "acts on deformable (MAILx) bodies in a way lmgc does not offer yet"}


def _missing(name):
    entry = _chipy.catalogue_entry(name)
    what = ""
    if entry is not None and entry[1]:
        what = " (it " + entry[1] + ")"
    reason = _SUPPORT_NOT_RUN.get(entry[0], "is not offered by lmgc") if entry is not None else \
        "is not offered by lmgc"

    def not_offered(*args, **kwargs):
        raise NotImplementedError("chipy.%s%s %s; docs/chipy.md lists the calls lmgc offers, and "
                                  "lmgc-solve --help the run parameters it takes" % (name, what, reason))
    not_offered.__name__ = name
    not_offered.lmgc_missing = True
    return not_offered


# Every chipy name the catalogue knows gets a function, so that `from pylmgc90.chipy import *` gives a
# script the call it uses, and that call says why it cannot run.
for _name in _chipy.catalogue_names():
    if _name not in globals():
        globals()[_name] = _missing(_name)
        __all__.append(_name)


def __getattr__(name):
    """A chipy name lmgc does not define: a function that raises NotImplementedError when called
    (a script may import it and never call it)."""
    if name.startswith("__"):
        raise AttributeError(name)
    return _missing(name)

#include "grammar/common/diagnostic_catalogue.hpp"

#include <algorithm>
#include <array>

namespace lmgc::grammar {
namespace {

using enum Severity;

// Sorted by code. Wording rules: lower-case start, no final period.
constexpr std::array kCatalogue = {
    // L1xxx — syntax: what the grammar of a file kind rejects or warns about.
    DiagnosticKind{"L1001", error, "unknown keyword",
                   "A card, body, element, node, contactor, law or command keyword is not one that "
                   "LMGC90 knows for this file and place. Keywords are case-sensitive and are read "
                   "from fixed columns (columns 2-6 for most cards)."},
    DiagnosticKind{"L1002", error, "malformed number",
                   "A numeric field does not hold a Fortran real: an optional sign, digits with at "
                   "most one decimal point, and an optional exponent written with D, d, E or e (or a "
                   "bare signed exponent). Blanks inside the field are ignored; an all-blank field "
                   "reads as zero."},
    DiagnosticKind{"L1003", error, "number out of range",
                   "The value does not fit: a real overflows double precision or its magnitude exceeds "
                   "1e100 (beyond any physical quantity: the masses, inertias and stiffnesses a run forms "
                   "from it would overflow), or an integer does not fit its field or is outside the range "
                   "the card allows."},
    DiagnosticKind{"L1004", error, "malformed integer",
                   "An integer field holds something other than an optional sign and digits."},
    DiagnosticKind{"L1005", error, "missing end of block",
                   "A block (a body in BODIES.DAT, a body in DRV_DOF.DAT, DOF.INI or GPV.INI) is not "
                   "closed by its '$$$$$$' line before the next block or the end of the file."},
    DiagnosticKind{"L1006", error, "unexpected end of file",
                   "The file ends in the middle of a card that needs more lines (continuation lines "
                   "of a polygon, a node with more than three values, a law parameter line, ...)."},
    DiagnosticKind{"L1007", warning, "tab character in a read field",
                   "A tab sits inside columns that LMGC90 reads. Fortran's treatment of tabs in "
                   "fixed-column input depends on the compiler; lmgc reads it as a blank. Replace "
                   "tabs by spaces."},
    DiagnosticKind{"L1008", error, "non-ASCII byte",
                   "LMGC90 files are plain ASCII text; a byte above 127 (often a UTF-8 character "
                   "pasted from a document) or a control character other than a tab (a NUL of a damaged "
                   "or binary file) is not allowed."},
    DiagnosticKind{"L1009", error, "empty file",
                   "The file holds no card at all (only blank or comment lines, or nothing)."},
    DiagnosticKind{"L1010", warning, "text beyond column 180",
                   "LMGC90 reads records of 180 characters: what is written past column 180 is "
                   "silently ignored."},
    DiagnosticKind{"L1011", warning, "value outside its columns",
                   "A value spills over the fixed columns it must occupy (for instance a real "
                   "shifted right by one column). LMGC90 reads only the field's columns and so "
                   "sees a different number than the one written; lmgc reads what LMGC90 reads "
                   "and says so. Align the value on its columns."},
    DiagnosticKind{"L1012", error, "missing section",
                   "A mandatory section or line is absent: '$gravy' in BULK_BEHAV.DAT, '$steps' in "
                   "DOF.INI, '$nodty' in a body, the title line of a '$seety' block, ..."},
    DiagnosticKind{"L1013", error, "unexpected line",
                   "A line appears where the file's structure requires another card (for instance "
                   "a data line outside any block)."},
    DiagnosticKind{"L1014", error, "wrong number of items",
                   "A card has the wrong number of items: an RBDY2 or RBDY3 body with other than one "
                   "node, a polygon with fewer than three vertices, ..."},
    DiagnosticKind{"L1015", error, "missing value",
                   "A value that LMGC90 reads list-directed (polyhedron counts and face indices, "
                   "evolution pairs, ...) is blank; Fortran stops with a runtime error there."},
    DiagnosticKind{"L1016", error, "wrong label",
                   "A label that LMGC90 checks is not the expected one ('elas:', 'ani_:', 'model', "
                   "'I1', 'localframe', 'n(1)=', ...)."},
    DiagnosticKind{"L1017", error, "invalid option value",
                   "A word is not one of the values allowed at this place (an anisotropy, a model "
                   "option, a driven dof kind, ...)."},
    DiagnosticKind{"L1018", note, "user's guide spelling accepted",
                   "The file uses the spelling of LMGC90's 2012 user's guide where LMGC90's source "
                   "reads another ('$gravity' for '$gravy', ...). lmgc reads both and writes "
                   "LMGC90's form; LMGC90 itself would reject the guide's form."},
    DiagnosticKind{"L1019", warning, "text ignored by LMGC90",
                   "A line sits outside every structure LMGC90 recognises (between two blocks, "
                   "after the last one): LMGC90 skips it silently. It is kept and echoed."},
    DiagnosticKind{"L1020", error, "mismatched header",
                   "The '$steps' header of an initial-state file does not match DOF.INI (step "
                   "number or time)."},
    DiagnosticKind{"L1021", note, "file not read by LMGC90",
                   "DATBOX/ holds a file that LMGC90's current reader never opens (a legacy or "
                   "pre-processor file such as SAMPLE.DAT or BEHAVIOURS.DAT). It is not checked."},
    DiagnosticKind{"L1022", warning, "damaged field label",
                   "A label of a DOF.INI node line ('X(1)=', 'V(2)=', ...) is not the one LMGC90 writes "
                   "there. LMGC90 reads the values by their columns and never reads the labels, so the "
                   "value is taken; a damaged label often means a damaged line: check its columns."},
    DiagnosticKind{"L1023", warning, "node type ignored by LMGC90",
                   "The node line of a rigid body's block in DRV_DOF.DAT names another node type than the "
                   "body's (NO3xx for RBDY2, NO6xx for RBDY3). LMGC90 checks only that it is a node type and "
                   "drives the dofs of the body's own node; lmgc does the same and echoes the body's type."},
    // L2xxx — cross references between files.
    DiagnosticKind{"L2001", error, "unknown bulk behaviour",
                   "A body names a bulk behaviour ('behav' of its PLAIN or model line) that "
                   "BULK_BEHAV.DAT does not define."},
    DiagnosticKind{"L2002", error, "unknown contact law",
                   "A '$seety' row names a law nickname that TACT_BEHAV.DAT does not define."},
    DiagnosticKind{"L2003", error, "unknown body",
                   "A body number in DRV_DOF.DAT, DOF.INI, GPV.INI or POSTPRO.DAT does not exist among the "
                   "bodies of that type in BODIES.DAT (bodies are numbered by order within their type). "
                   "Vloc_Rloc.INI is reported by L2007."},
    DiagnosticKind{"L2004", error, "unknown model",
                   "A MAILx element names a model that MODELS.DAT does not define."},
    DiagnosticKind{"L2005", error, "unknown element node",
                   "An element connectivity or a MAILx contactor names a node number that its body does "
                   "not have."},
    DiagnosticKind{"L2006", error, "unknown node",
                   "DRV_DOF.DAT, DOF.INI or POSTPRO.DAT names a node that the body does not have, or GPV.INI "
                   "names an element that the body does not have (or of another type)."},
    DiagnosticKind{
        "L2007", warning, "initial interaction names a missing contactor",
        "An interaction of Vloc_Rloc.INI names a body that does not exist, a contactor number that "
        "its body does not have, or a contactor of another type. LMGC90's read_ini_Vloc_Rloc finds "
        "no contactor to attach it to and skips it silently: its initial reaction and internal "
        "variables are lost."},
    DiagnosticKind{"L2008", error, "unknown dof",
                   "A driven dof number is larger than the number of dofs of its node (NO3xx has 3)."},
    DiagnosticKind{"L2009", error, "element incompatible with its model",
                   "A MAILx element names a model whose finite element is for another element shape or node "
                   "count (a T3xxx model on a Q4xxx element). LMGC90 takes the element of the model and the "
                   "connectivity of the body, and computes with mismatched arrays. Q4P0x is a Q4xxx, Q8Rxx a "
                   "Q8xxx, H20Rx a H20xx, SHB6x a PRI6x."},
    DiagnosticKind{"L2010", warning, "visibility row never matches",
                   "No contactor of the type and colour named by a '$seety' row exists, so the row never "
                   "creates a contact. Often a misspelt colour."},
    DiagnosticKind{"L2011", note, "contactors in no visibility row",
                   "Contactors of this type and colour appear in no '$seety' row: they never touch "
                   "anything. Intended for decorations, a mistake otherwise."},
    DiagnosticKind{"L2012", warning, "duplicate definition",
                   "A nickname (contact law, bulk behaviour, model) is defined twice, and LMGC90 uses the "
                   "first; or a dof of DRV_DOF.DAT is driven twice, or DOF.INI gives a body's initial state "
                   "twice."},
    DiagnosticKind{"L2013", error, "dimension mismatch",
                   "A body, node, element or contactor belongs to the other dimension than the case: LMGC90 "
                   "runs in 2D (RBDY2 bodies, NO2xx nodes, T3xxx/Q4xxx elements, CLxxx/ALpxx contactors) or "
                   "in 3D (RBDY3 bodies, NO3xx MAILx nodes, H8xxx/TE4xx elements, CSpxx/ASpxx contactors), "
                   "never both; the case's dimension is set by its first rigid body, else by its MAILx "
                   "nodes."},
    DiagnosticKind{"L2014", warning, "no interaction for this pair",
                   "LMGC90 has no interaction module for this candidate/antagonist contactor pair in this "
                   "order (for instance JONCx as candidate of a DISKx). The row creates no contact."},
    DiagnosticKind{"L2015", error, "conflicting visibility rows",
                   "Two '$seety' rows give different laws to the same pair of contactor classes (in either "
                   "order); LMGC90 stops on this."},
    // L3xxx — physical sanity.
    DiagnosticKind{"L2016", error, "evolution times not increasing",
                   "An evolution file named by DRV_DOF.DAT has a time that is not after the time before it. "
                   "LMGC90 stops on two equal consecutive times, and its interpolation assumes increasing "
                   "times."},
    DiagnosticKind{"L2017", note, "body number is not its rank",
                   "LMGC90 numbers the bodies of BODIES.DAT by order of appearance within their type and "
                   "never reads the number written after the type. DRV_DOF.DAT, DOF.INI, Vloc_Rloc.INI, "
                   "GPV.INI and POSTPRO.DAT name bodies by that rank, so a body written with another number "
                   "is easily driven or tracked by mistake. Said once per body type, at the first mismatch."},
    DiagnosticKind{
        "L2018", error, "contact law not usable for this interaction",
        "A '$seety' row gives a law that LMGC90's NLGS cannot apply to the row's interaction in the "
        "case's dimension: the law has no variant in this dimension ('Unsupported nbDIME'), or "
        "prep_nlgs stops with 'not implemented for this contact element' (cohesive zone laws need "
        "a contact length or surface: in 2D MAC_CZM and the gap CZMs work with CLALp, CLJCx, "
        "PLALp, DKALp, IQS_MAC_CZM and the IQS CZMs with DKDKx, DKJCx, PLPLx, PLJCx, DKDKL; in 3D "
        "the gap CZMs with CSASp, CSPRx, PRASp, the IQS CZMs with rigid contactors; NARD_ROD only "
        "with PTPT2/PTPT3)."},
    DiagnosticKind{
        "L2019", error, "invalid model options",
        "A model of MODELS.DAT lacks an option, or has a value, that LMGC90 stops on when it sets up "
        "its models (init_models): 'isext' is "
        "mandatory; with 'isext no___' (LMGC90's own elements) a mechanical model needs 'kine_' "
        "small or large, 'kine_ large' needs 'form_ UpdtL' (MULTI has no large deformations), and a "
        "THERM model needs 'form_' class or discr. Other 'isext' values hand the model to an external "
        "library, which checks its own options."},
    DiagnosticKind{
        "L2020", error, "bulk behaviour lacks what its user needs",
        "A bulk behaviour is used where it cannot work: a rigid body whose behaviour has no density "
        "(DISCRETE, JOINT_*), a mechanical model whose behaviour has no ELAS block (Young's modulus, "
        "Poisson ratio), a J2 plasticity model ('mater J2...') without a PLAS block, a THERM model "
        "without a THERM block (heat capacity, conductivity)."},
    DiagnosticKind{"L2021", error, "unknown point in the PTPT3 network",
                   "A link of PTPT3_NETWORK.DAT names a point (icdtac or iantac) that is not among the "
                   "case's PT3Dx contactors, which are numbered 1, 2, ... in BODIES.DAT order over all "
                   "RBDY3 bodies. LMGC90 reads past its array."},
    DiagnosticKind{"L2022", error, "PTPT3 link without a visibility row",
                   "A link of PTPT3_NETWORK.DAT joins two PT3Dx whose colours no PT3Dx/PT3Dx '$seety' "
                   "row names (in either order, as LMGC90's get_isee reads rows): the link has no law "
                   "(get_isee returns 0 and LMGC90 fails later); or it joins two points of the same "
                   "body, whose distance never changes (LMGC90 keeps such a link; lmgc-solve refuses it)."},
    DiagnosticKind{
        "L3001", error, "non-positive size",
        "A radius, half length, half thickness or height of a contactor is zero or negative, or an "
        "avrd/gyrd is negative."},
    DiagnosticKind{
        "L3002", error, "non-positive density",
        "The density 'Umas' of a bulk behaviour is negative, or zero while a rigid body uses it (a "
        "rigid body's mass is its density times its area or volume). A zero density is accepted for "
        "deformable bodies (quasi-static runs)."},
    DiagnosticKind{
        "L3003", error, "non-positive stiffness",
        "A stiffness-like parameter (Young's or shear modulus of an ELAS block, a spring stiffness "
        "of a contact law) is zero or negative."},
    DiagnosticKind{"L3004", error, "Poisson ratio out of range",
                   "The Poisson ratio 'EPss' of an isotropic ELAS block is outside (-1, 0.5): the elastic "
                   "energy is then not positive (0.5 itself is incompressible and makes the elastic matrix "
                   "singular)."},
    DiagnosticKind{"L3005", error, "negative friction",
                   "A friction coefficient is negative; Coulomb's law needs mu >= 0."},
    DiagnosticKind{"L3006", error, "restitution out of range",
                   "A restitution coefficient is outside [0, 1]; above 1 impacts would create energy."},
    DiagnosticKind{"L3007", error, "non-positive alert distance",
                   "An alert distance is zero or negative: the detection creates no contact at all."},
    DiagnosticKind{"L3008", warning, "alert distance out of scale",
                   "The alert distance is larger than the contactors it applies to (many far contacts, "
                   "slow solves) or negligible against them (fast contacts missed)."},
    DiagnosticKind{"L3009", error, "bad polygon",
                   "A POLYG is clockwise (LMGC90 stops on a negative area), degenerate (zero area), "
                   "self-intersecting, or has fewer than 3 vertices."},
    DiagnosticKind{
        "L3010", error, "bad polyhedron",
        "A POLYR is not a closed surface (an edge not shared by exactly two faces), has a zero-area "
        "face, or a face naming a missing vertex. The order of a face's vertices does not matter: "
        "LMGC90 orients the faces consistently and outward itself."},
    DiagnosticKind{"L3011", error, "non-positive Jacobian",
                   "A finite element is inverted or degenerate at one of its nodes (nodes must turn "
                   "counter-clockwise in 2D; positive volume in 3D)."},
    DiagnosticKind{
        "L3012", warning, "initial interpenetration",
        "Two rigid contactors that a visibility row lets touch overlap at the start by more than "
        "0.1 % of the smaller one (disks and spheres against each other, against JONCx walls and "
        "PLANx boxes; positions from BODIES.DAT plus DOF.INI displacements, RBDY3 bodies turned by "
        "DOF.INI's frame). With IQS laws LMGC90 keeps the overlap for the whole run; with GAP laws it "
        "removes it in one step, which throws the bodies apart. The first 20 pairs are named, the "
        "rest counted."},
    DiagnosticKind{
        "L3013", warning, "time step too large",
        "COMMAND.DAT's time step dt is large against a time scale of the case. (1) Penalty laws "
        "(parameter F/gap = k, ELASTIC_REPELL_CLB and relatives) on the lightest free body of mass m "
        "the law applies to: warning when dt > sqrt(m/k), i.e. fewer than 2 pi steps per period "
        "2 pi sqrt(m/k) of the contact spring. (2) Free fall: a disk or sphere that falls a height "
        "d down to the first contactor below it that it may touch reaches v = sqrt(2 g d) and moves "
        "v dt per step; warning when v dt exceeds the alert distance of the pair, since the contact "
        "is then first detected already penetrated (equivalently, the fall lasts longer than "
        "alert / (g dt), the time after which a body falling from rest moves more than the alert "
        "distance per step). Masses come from 'Umas' and avrd or the contactors; bodies whose "
        "translation is driven do not fall."},
    DiagnosticKind{"L3014", warning, "nothing loads the case",
                   "Gravity is zero (in the plane of a 2D case), no driven dof imposes a non-zero value and "
                   "DOF.INI gives no body a velocity: nothing can move. Often a forgotten '$gravy' value."},
    DiagnosticKind{"L3016", warning, "dynamic friction above static friction",
                   "A law's dynamic friction coefficient is larger than its static one; usually the two are "
                   "swapped."},
    DiagnosticKind{
        "L3017", warning, "duplicate element",
        "Two elements of a MAILx body have the same nodes: the mesh's stiffness and mass count that "
        "part twice. Usually a mesh written twice or a merge of overlapping meshes."},
    DiagnosticKind{"L3018", error, "degenerate contactor of a mesh",
                   "A CLxxx whose two nodes are one point (or whose apab is outside [0, 1]), or a segment "
                   "of an ALpxx whose two nodes are one point: the contactor has no direction, and "
                   "LMGC90 divides by its zero length when it computes its normal."},
    // L4xxx — run setup: what lmgc-solve does with the case. The codes that refuse a run are
    // warnings here (the case is valid for LMGC90) and make lmgc-solve stop with exit code 5.
    DiagnosticKind{"L4001", warning, "contactor not run by lmgc-solve yet",
                   "The case uses a contactor kind that lmgc-solve does not provide yet for this "
                   "dimension. The case is valid for LMGC90; lmgc-solve refuses it (exit 5) rather than "
                   "run it without those contactors.",
                   false, true},
    DiagnosticKind{"L4002", warning, "contact law not run by lmgc-solve yet",
                   "A '$seety' row uses a contact law that lmgc-solve does not solve yet. lmgc-solve "
                   "refuses the case (exit 5) rather than silently use another law.",
                   false, true},
    DiagnosticKind{"L4003", warning, "case kind not run by lmgc-solve yet",
                   "lmgc-solve runs cases of RBDY2 bodies only or of RBDY3 bodies only for now; a case with "
                   "MAILx bodies, or mixing body types, is checked by lmgc-check and refused by "
                   "lmgc-solve (exit 5).",
                   false, true},
    DiagnosticKind{
        "L4004", warning, "post-processing command not computed",
        "A POSTPRO.DAT command that lmgc-solve does not compute yet for this kind of case: its file is "
        "not written. The run itself is the same."},
    DiagnosticKind{"L4005", warning, "command not run by lmgc-solve yet",
                   "A command of the case's driver (COMMAND.DAT, or a chipy call of command.py) changes "
                   "the physics or the course of the run, and lmgc-solve does not do it yet (damping, "
                   "wall drivers, another integrator or detection method, bodies driven from Python, "
                   "...). lmgc-solve refuses the case (exit 5) rather than run another problem. For a "
                   "COMMAND.DAT, which LMGC90 2025 no longer reads, `lmgc-solve --no-command-dat` runs "
                   "the case from its defaults and flags instead.",
                   false, true},
    DiagnosticKind{"L4006", note, "output or warm start not reproduced",
                   "A command asks for an output lmgc-solve does not write (a display option, a binary or "
                   "timer file) or for a warm start by position, which lmgc-solve does by contactor: the "
                   "problem solved is the same; the files written, or the NLGS's first iterate, differ."},
    DiagnosticKind{"L4007", warning, "multi-physics not run by lmgc-solve yet",
                   "The case asks for LMGC90's thermal or electrical fields on rigid bodies (MP_DEM: "
                   "MP_DEM.DAT, ReadMpBehaviours, READ MP BEHAVIOURS) or for PTPT2 links "
                   "(PTPT2_NETWORK.DAT). lmgc-solve refuses it (exit 5). THERMO_RIGID, ELECTRO_RIGID and "
                   "THERMO_ELECTRO_RIGID bulk laws alone are run as RIGID, as LMGC90 runs them when the "
                   "script loads no multi-physics behaviour (a note says so).",
                   false, true},
    DiagnosticKind{"L4008", warning, "run parameter differs from command.py",
                   "The case has a command.py, the script LMGC90 runs, and lmgc-solve took this run "
                   "parameter from a flag (or, with --command-dat, from COMMAND.DAT or its default) with "
                   "a value other than the script's. Leave the flag out to run as the script does."},
    DiagnosticKind{"L4009", note, "chipy call not known to lmgc",
                   "command.py calls a chipy function that lmgc does not know: its effect on the run "
                   "is not checked."},
    DiagnosticKind{"L4010", error, "run parameter out of range",
                   "A run parameter of COMMAND.DAT, or a literal that command.py passes to the chipy "
                   "call that sets it, is outside the values a run can take: a time step, "
                   "tolerance or iteration count not positive, a theta outside [0.5, 1], a relaxation "
                   "outside (0, 2], a non-positive period or output frequency, an unknown NLGS norm or "
                   "storage."},
    DiagnosticKind{"L4011", warning, "command.py present",
                   "The case has a command.py: LMGC90 2025 runs it and no longer reads COMMAND.DAT, and "
                   "so does lmgc-solve (through lmgc-run). With --read-script or a run-parameter flag, "
                   "lmgc-solve runs its own loop instead: it reads the script and takes the run "
                   "parameters its chipy calls pass as literals (time step, theta, the step loop's "
                   "count, the NLGS's settings, output frequencies, boundaries, periods, ...), then the "
                   "flags; COMMAND.DAT is not read (--command-dat reads it instead of the script). What "
                   "the script computes is named (L4013), what it does that lmgc-solve does not is "
                   "refused (L4005), and every flag that overrides the script is named (L4008)."},
    DiagnosticKind{"L4012", note, "multi-physics bulk parameters not used",
                   "A THERMO_RIGID, ELECTRO_RIGID or THERMO_ELECTRO_RIGID bulk law gives thermal or "
                   "electrical parameters that only LMGC90's multi-physics solver uses (when the script "
                   "loads MP_DEM.DAT). Without it LMGC90 runs the body as RIGID, and so does lmgc-solve."},
    DiagnosticKind{"L4013", warning, "run parameter computed by command.py",
                   "command.py sets a run parameter with a value computed at run time (a function call, "
                   "a name bound under a condition, input read from a file) that lmgc-solve --read-script, "
                   "which reads the script without running it, cannot know (lmgc-check reports it with "
                   "--read-script). The message names the value lmgc-solve "
                   "runs instead and the flag that sets it: give the flag with the script's value."},
    // L9xxx — input/output.
    DiagnosticKind{"L9001", error, "cannot read file",
                   "A file that the case needs does not exist or cannot be read."},
    DiagnosticKind{"L9002", error, "not a case folder",
                   "The folder given does not exist or has no DATBOX/ sub-folder."},
    DiagnosticKind{"L9003", error, "cannot write output",
                   "An output file could not be written (folder not writable, disk full, ...). "
                   "Existing outputs are left as they were."},
    DiagnosticKind{"L9004", error, "diagnostics not shown",
                   "More diagnostics arrived than are kept (5000): the count of those not shown is given "
                   "by severity. Errors are kept before warnings and notes, so an error is dropped only "
                   "when 5000 errors are already shown. Fix those and check again."},
};

}  // namespace

std::span<const DiagnosticKind> diagnostic_catalogue() {
  return kCatalogue;
}

bool refuses_run(std::string_view code) {
  const DiagnosticKind* kind = find_diagnostic_kind(code);
  return kind && kind->refuses_run;
}

const DiagnosticKind* find_diagnostic_kind(std::string_view code) {
  auto it = std::lower_bound(kCatalogue.begin(), kCatalogue.end(), code,
                             [](const DiagnosticKind& k, std::string_view c) { return k.code < c; });
  if (it == kCatalogue.end() || it->code != code) return nullptr;
  return &*it;
}

}  // namespace lmgc::grammar

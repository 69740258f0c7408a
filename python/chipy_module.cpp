// lmgc._chipy: the C++ chipy session (chipy/session.hpp) for Python. lmgc/chipy/__init__.py gives
// LMGC90's function names, argument names and defaults on top of it; this module only converts:
// arguments in, numpy arrays out (one copy: the session's values are moved into the array's
// buffer), and the session's errors into Python exceptions.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "chipy/session.hpp"
#include "grammar/command_py/chipy_catalogue.hpp"

namespace py = pybind11;
using lmgc::chipy::ErrorKind;
using lmgc::chipy::Reading;
using lmgc::chipy::Session;

namespace {

// A numpy array over a vector's buffer, which the array then owns: no copy.
py::array_t<double> to_array(std::vector<double>&& values, std::vector<py::ssize_t> shape) {
  auto* owned = new std::vector<double>(std::move(values));
  py::capsule owner(owned, [](void* p) { delete static_cast<std::vector<double>*>(p); });
  std::vector<py::ssize_t> strides(shape.size(), static_cast<py::ssize_t>(sizeof(double)));
  for (std::size_t k = shape.size(); k-- > 1;) strides[k - 1] = strides[k] * shape[k];
  return py::array_t<double>(shape, strides, owned->data(), owner);
}

template <class T>
py::array_t<T> copy_array(const std::vector<T>& values) {
  py::array_t<T> a(static_cast<py::ssize_t>(values.size()));
  std::copy(values.begin(), values.end(), a.mutable_data());
  return a;
}

std::vector<double> as_vector(const py::array_t<double, py::array::c_style | py::array::forcecast>& a) {
  return std::vector<double>(a.data(), a.data() + a.size());
}

}  // namespace

PYBIND11_MODULE(_chipy, m) {
  m.doc() = "lmgc's chipy session (use lmgc.chipy, which has LMGC90's names)";

  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const lmgc::chipy::Error& e) {
      switch (e.kind) {
        case ErrorKind::order:
        case ErrorKind::data:
          PyErr_SetString(PyExc_RuntimeError, e.what());
          return;
        case ErrorKind::index:
          PyErr_SetString(PyExc_IndexError, e.what());
          return;
        case ErrorKind::value:
          PyErr_SetString(PyExc_ValueError, e.what());
          return;
        case ErrorKind::not_implemented:
          PyErr_SetString(PyExc_NotImplementedError, e.what());
          return;
        case ErrorKind::non_finite:
          PyErr_SetString(PyExc_FloatingPointError, e.what());
          return;
        case ErrorKind::output:
          PyErr_SetString(PyExc_OSError, e.what());
          return;
        case ErrorKind::newton_diverged:
          // The script ends with lmgc-run's own exit code, the message on stderr.
          PySys_WriteStderr("lmgc: %s\n", e.what());
          PyErr_SetObject(PyExc_SystemExit, py::int_(lmgc::chipy::kNewtonDivergedExit).ptr());
          return;
        case ErrorKind::step_limit:
          // The script ends there, as a successful run: SystemExit(0) is not caught by
          // `except Exception` in a script.
          PyErr_SetObject(PyExc_SystemExit, py::int_(0).ptr());
          return;
      }
    }
  });

  py::enum_<Reading>(m, "Reading")
      .value("behaviours", Reading::behaviours)
      .value("bodies", Reading::bodies)
      .value("load_behaviours", Reading::load_behaviours)
      .value("ini_dof", Reading::ini_dof)
      .value("driven_dof", Reading::driven_dof)
      .value("tactors", Reading::tactors)
      .value("ini_vloc_rloc", Reading::ini_vloc_rloc);

  py::class_<Session>(m, "Session")
      .def(py::init([](const std::filesystem::path& dir, long max_steps, bool quiet) {
             return std::make_unique<Session>(dir, lmgc::chipy::SessionOptions{max_steps, quiet});
           }),
           py::arg("case_dir"), py::arg("max_steps") = -1, py::arg("quiet") = false)
      .def("set_dimension", &Session::set_dimension)
      .def("dimension", &Session::dimension)
      .def("set_time_step", &Session::set_time_step)
      .def("time_step", &Session::time_step)
      .def("time", &Session::time)
      .def("step", &Session::step)
      .def("steps_done", &Session::steps_done)
      .def("init_theta", &Session::init_theta)
      .def("set_quick_scramble", &Session::set_quick_scramble)
      .def("set_diagonal_resolution", &Session::set_diagonal_resolution)
      .def("set_periodic", &Session::set_periodic)
      .def("set_boundary", &Session::set_boundary)
      .def("new_rotation_scheme", &Session::new_rotation_scheme)
      .def("set_source_point", &Session::set_source_point)
      .def("set_cundall_iterations", &Session::set_cundall_iterations)
      .def("ptpt3_load_network", &Session::ptpt3_load_network)
      .def("ptpt3_use_current_nonuc0", &Session::ptpt3_use_current_nonuc0)
      .def("read", &Session::read)
      .def("write_echo", &Session::write_echo)
      .def("compute_mass", &Session::compute_mass)
      .def("stage", &Session::stage)
      .def("recup_rloc", &Session::recup_rloc)
      .def("select_prox_tactors", &Session::select_prox_tactors)
      .def("ex_solver", &Session::ex_solver)
      .def("write_out_dof", &Session::write_out_dof)
      .def("write_out_vloc_rloc", &Session::write_out_vloc_rloc)
      .def("write_last_dof", &Session::write_last_dof)
      .def("write_last_vloc_rloc", &Session::write_last_vloc_rloc)
      .def("write_out_gpv", &Session::write_out_gpv)
      .def("write_last_gpv", &Session::write_last_gpv)
      .def("has_deformable_bodies", &Session::has_deformable_bodies)
      .def("has_contact_laws", &Session::has_contact_laws)
      .def("set_rayleigh_damping", &Session::set_rayleigh_damping)
      .def("set_newton_parameter", &Session::set_newton_parameter)
      .def("newton_initialize", &Session::newton_initialize)
      .def("newton_check_convergence", &Session::newton_check_convergence)
      .def("newton_compute_time_step", &Session::newton_compute_time_step)
      .def("residue_norm", &Session::residue_norm)
      .def("open_display", &Session::open_display)
      .def("write_display", &Session::write_display)
      .def("close_display", &Session::close_display)
      .def("open_postpro", &Session::open_postpro)
      .def("write_postpro", &Session::write_postpro)
      .def("close_postpro", &Session::close_postpro)
      .def("finalize", &Session::finalize)
      .def("body_count", &Session::body_count)
      .def("body_vector",
           [](const Session& s, int dimension, const std::string& name, long body) {
             std::vector<double> v = s.body_vector(dimension, name, body);
             const auto n = static_cast<py::ssize_t>(v.size());
             return to_array(std::move(v), {n});
           })
      .def("all_body_vectors",
           [](const Session& s, int dimension, const std::string& name) {
             std::size_t size = 0;
             std::vector<double> v = s.all_body_vectors(dimension, name, size);
             const auto rows = static_cast<py::ssize_t>(size ? v.size() / size : 0);
             return to_array(std::move(v), {rows, static_cast<py::ssize_t>(size)});
           })
      .def("put_body_vector",
           [](Session& s, int dimension, const std::string& name, long body,
              const py::array_t<double, py::array::c_style | py::array::forcecast>& value) {
             if (value.ndim() != 1)
               throw lmgc::chipy::Error(ErrorKind::value,
                                        "PutBodyVector: the vector must be one-dimensional");
             const std::vector<double> v = as_vector(value);
             s.put_body_vector(dimension, name, body, v);
           })
      .def("set_vlocy_driven_dof", &Session::set_vlocy_driven_dof)
      .def("body_mass", &Session::body_mass)
      .def("body_visible", &Session::body_visible)
      .def("contactors",
           [](const Session& s, const std::string& type) {
             const auto list = s.contactors(type);
             py::array_t<int> a({static_cast<py::ssize_t>(list.size()), py::ssize_t{3}});
             auto m = a.mutable_unchecked<2>();
             for (std::size_t k = 0; k < list.size(); ++k) {
               m(k, 0) = static_cast<int>(list[k].first);
               m(k, 1) = static_cast<int>(list[k].second);
               m(k, 2) = s.dimension() == 3 ? 2 : 1;  // LMGC90's body model ids: RBDY2 1, RBDY3 2
             }
             return a;
           })
      .def("interactions", [](const Session& s) {
        Session::Interactions i = s.interactions();
        const auto n = static_cast<py::ssize_t>(i.module.size());
        const py::ssize_t d = s.dimension();
        py::dict out;
        out["inter"] = i.module;
        out["icdan"] = copy_array(i.number);
        out["cdbdy"] = i.candidate_body_type;
        out["anbdy"] = i.antagonist_body_type;
        out["icdbdy"] = copy_array(i.candidate_body);
        out["ianbdy"] = copy_array(i.antagonist_body);
        out["cdtac"] = i.candidate_type;
        out["antac"] = i.antagonist_type;
        out["icdtac"] = copy_array(i.candidate_contactor);
        out["iantac"] = copy_array(i.antagonist_contactor);
        out["behav"] = i.law;
        out["status"] = i.status;
        out["coor"] = to_array(std::move(i.point), {n, d});
        out["uc"] = to_array(std::move(i.frame), {n, d, d});
        out["rl"] = to_array(std::move(i.rl), {n, d});
        out["vl"] = to_array(std::move(i.vl), {n, d});
        out["gapTT"] = to_array(std::move(i.gap), {n});
        return out;
      });

  // The chipy names of the catalogue matched exactly (lmgc.chipy defines a function for each).
  m.def("catalogue_names", [] {
    std::vector<std::string> names;
    for (const lmgc::grammar::ChipyFunction& f : lmgc::grammar::chipy_catalogue())
      if (f.match == lmgc::grammar::ChipyMatch::exact) names.emplace_back(f.name);
    return names;
  });

  // What lmgc-solve's reading of a script says of a chipy name: (support, what it does), or None.
  m.def("catalogue_entry", [](const std::string& name) -> py::object {
    const lmgc::grammar::ChipyFunction* f = lmgc::grammar::find_chipy_function(name);
    if (!f) return py::none();
    return py::make_tuple(static_cast<int>(f->support), std::string(f->what));
  });
}

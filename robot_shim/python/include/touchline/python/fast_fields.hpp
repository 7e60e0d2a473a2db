#pragma once
// Read-write attributes of pybind11 classes as plain CPython getset descriptors: what
// def_readwrite does, without pybind11's dispatch on every read and write (a behaviour
// builds its request with a dozen of them every tick: robot.Body(), body.forward = ...).
// The class stays a pybind11 class (constructors, casts to and from C++ as before).
// Values convert as pybind11 converts them: floats from anything with __float__ (rounded to
// float as a C cast does), ints from anything with __index__ (range-checked), bools from
// bools, None and numbers; enums and classes through pybind11's own casters. A struct
// member reads as a reference into its owner (def_readwrite's reference_internal):
// request.body.forward = 1 writes the request's body.
#include <pybind11/pybind11.h>

#include <cstdint>
#include <initializer_list>
#include <limits>
#include <stdexcept>
#include <type_traits>
#include <typeinfo>
#include <vector>

namespace touchline::python::fast_fields {

template <typename>
struct MemberOf;
template <typename Struct, typename Type>
struct MemberOf<Type Struct::*> {
  using Owner = Struct;
  using Value = Type;
};
template <typename Struct, typename Type>
struct MemberOf<Type (Struct::*)() const> {
  using Owner = Struct;
};

/// The C++ object a pybind11 instance holds (the descriptor has checked its type); null
/// with a Python error when it holds none (__init__ never ran).
template <typename T>
T* held(PyObject* self) {
  auto* inst = reinterpret_cast<pybind11::detail::instance*>(self);
  void* value = inst->simple_layout ? inst->simple_value_holder[0] : inst->get_value_and_holder().value_ptr();
  if (!value) PyErr_Format(PyExc_TypeError, "%s instance was not initialised (__init__ not called)", Py_TYPE(self)->tp_name);
  return static_cast<T*>(value);
}

/// pybind11's record of T, set when its class is defined (again in a new interpreter).
template <typename T>
pybind11::detail::type_info*& type_record() {
  static pybind11::detail::type_info* record = nullptr;
  return record;
}

/// Keeps pybind11's record of T (a class just defined) for cast_out and fast_default_init.
template <typename T>
void remember_type() {
  type_record<T>() = pybind11::detail::get_type_info(typeid(T));
  if (!type_record<T>()) throw std::logic_error("remember_type before the class is defined");
}

/// pybind11::cast(&v, policy, parent) of a class T, without looking its record up by
/// typeid at every call (pybind11's hash lookup) once remember_type<T>() has kept it.
template <typename T>
PyObject* cast_out(const T& v, pybind11::return_value_policy policy, PyObject* parent = nullptr) {
  const pybind11::detail::type_info* record = type_record<T>();
  if (!record) return pybind11::cast(&v, policy, parent).release().ptr();
  return pybind11::detail::type_caster_generic::cast(
             &v, policy, parent, record, [](const void* p) -> void* { return new T(*static_cast<const T*>(p)); },
             nullptr)
      .ptr();
}

inline PyObject* read(float v, PyObject*) { return PyFloat_FromDouble(static_cast<double>(v)); }
inline PyObject* read(bool v, PyObject*) { return PyBool_FromLong(v); }
inline PyObject* read(int32_t v, PyObject*) { return PyLong_FromLong(v); }
inline PyObject* read(int64_t v, PyObject*) { return PyLong_FromLongLong(v); }
inline PyObject* read(const std::vector<uint8_t>& v, PyObject*) { // bytes, a copy
  return PyBytes_FromStringAndSize(reinterpret_cast<const char*>(v.data()), static_cast<Py_ssize_t>(v.size()));
}
template <typename T>
PyObject* read(const T& v, PyObject* owner) {
  if constexpr (std::is_enum_v<T>) {
    return pybind11::cast(v).release().ptr(); // a fresh enum instance
  } else { // a reference into the owner, which it keeps alive
    return cast_out(v, pybind11::return_value_policy::reference_internal, owner);
  }
}

/// False with a TypeError when `value` is not one.
inline bool write(float& out, PyObject* value) {
  const double d = PyFloat_CheckExact(value) ? PyFloat_AS_DOUBLE(value) : PyFloat_AsDouble(value);
  if (d == -1.0 && PyErr_Occurred()) return false;
  out = static_cast<float>(d);
  return true;
}
inline bool write(bool& out, PyObject* value) {
  if (value == Py_True || value == Py_False || value == Py_None) {
    out = value == Py_True;
    return true;
  }
  PyNumberMethods* number = Py_TYPE(value)->tp_as_number;
  if (!number || !number->nb_bool) {
    PyErr_Format(PyExc_TypeError, "expected a bool, got %s", Py_TYPE(value)->tp_name);
    return false;
  }
  const int truth = number->nb_bool(value);
  if (truth < 0) return false;
  out = truth != 0;
  return true;
}
inline bool write(int32_t& out, PyObject* value) {
  if (PyFloat_Check(value) || !PyIndex_Check(value)) {
    PyErr_Format(PyExc_TypeError, "expected an int, got %s", Py_TYPE(value)->tp_name);
    return false;
  }
  const long long v = PyLong_AsLongLong(value);
  if (v == -1 && PyErr_Occurred()) return false;
  if (v < std::numeric_limits<int32_t>::min() || v > std::numeric_limits<int32_t>::max()) {
    PyErr_SetString(PyExc_TypeError, "int out of the 32-bit range");
    return false;
  }
  out = static_cast<int32_t>(v);
  return true;
}
template <typename T>
bool write(T& out, PyObject* value) {
  try {
    out = pybind11::cast<T>(pybind11::handle(value));
    return true;
  } catch (const pybind11::cast_error&) {
    PyErr_Format(PyExc_TypeError, "incompatible value: %s", Py_TYPE(value)->tp_name);
  } catch (pybind11::error_already_set& e) {
    e.restore();
  }
  return false;
}

template <auto Member>
PyObject* get(PyObject* self, void*) {
  using Owner = typename MemberOf<decltype(Member)>::Owner;
  Owner* owner = held<Owner>(self);
  if (!owner) return nullptr;
  try {
    return read(owner->*Member, self);
  } catch (pybind11::error_already_set& e) {
    e.restore();
  } catch (const std::exception& e) {
    PyErr_SetString(PyExc_RuntimeError, e.what());
  }
  return nullptr;
}

template <auto Member>
int set(PyObject* self, PyObject* value, void*) {
  using Owner = typename MemberOf<decltype(Member)>::Owner;
  if (!value) {
    PyErr_SetString(PyExc_AttributeError, "cannot delete a field");
    return -1;
  }
  Owner* owner = held<Owner>(self);
  if (!owner) return -1;
  typename MemberOf<decltype(Member)>::Value converted{};
  if (!write(converted, value)) return -1;
  owner->*Member = std::move(converted);
  return 0;
}

/// cls.name as a read-write attribute of Member (name and doc: literals, kept by the descriptor).
template <auto Member, typename Class>
void readwrite(Class& cls, const char* name, const char* doc = nullptr) {
  static PyGetSetDef def{name, &get<Member>, &set<Member>, doc, nullptr};
  PyObject* descriptor = PyDescr_NewGetSet(reinterpret_cast<PyTypeObject*>(cls.ptr()), &def);
  if (!descriptor) throw pybind11::error_already_set();
  cls.attr(name) = pybind11::reinterpret_steal<pybind11::object>(descriptor);
}

/// T() as __init__ of its pybind11 class, without pybind11's dispatch: what py::init<>()
/// does (a new T held by the instance, registered with pybind11), for requests a behaviour
/// builds several of every tick. A second __init__ on the same instance does nothing, as
/// in pybind11.
template <typename T>
PyObject* default_init(PyObject* self, PyObject* args, PyObject* kwargs) {
  if (PyTuple_GET_SIZE(args) != 0 || (kwargs && PyDict_GET_SIZE(kwargs) != 0)) {
    PyErr_Format(PyExc_TypeError, "%s() takes no arguments", Py_TYPE(self)->tp_name);
    return nullptr;
  }
  auto* inst = reinterpret_cast<pybind11::detail::instance*>(self);
  try {
    pybind11::detail::value_and_holder holder = inst->get_value_and_holder(type_record<T>());
    if (!holder.type || !holder.inst) {
      PyErr_SetString(PyExc_TypeError, "__init__ on an object that is not an instance of its class");
      return nullptr;
    }
    if (!holder.instance_registered()) {
      holder.value_ptr() = new T();
      holder.type->init_instance(inst, nullptr);
    }
  } catch (pybind11::error_already_set& e) {
    e.restore();
    return nullptr;
  } catch (const std::exception& e) {
    PyErr_SetString(PyExc_RuntimeError, e.what());
    return nullptr;
  }
  Py_RETURN_NONE;
}

template <typename T, typename Class>
void fast_default_init(Class& cls) {
  remember_type<T>();
  static PyMethodDef def{"__init__", reinterpret_cast<PyCFunction>(reinterpret_cast<void (*)()>(&default_init<T>)),
                         METH_VARARGS | METH_KEYWORDS, "a default request part"};
  PyObject* descriptor = PyDescr_NewMethod(reinterpret_cast<PyTypeObject*>(cls.ptr()), &def);
  if (!descriptor) throw pybind11::error_already_set();
  cls.attr("__init__") = pybind11::reinterpret_steal<pybind11::object>(descriptor);
}

/// cls.name as a read-only attribute of Member.
template <auto Member, typename Class>
void readonly(Class& cls, const char* name, const char* doc = nullptr) {
  static PyGetSetDef def{name, &get<Member>, nullptr, doc, nullptr};
  PyObject* descriptor = PyDescr_NewGetSet(reinterpret_cast<PyTypeObject*>(cls.ptr()), &def);
  if (!descriptor) throw pybind11::error_already_set();
  cls.attr(name) = pybind11::reinterpret_steal<pybind11::object>(descriptor);
}

template <auto Method>
PyObject* call_getter(PyObject* self, PyObject*) {
  using Owner = typename MemberOf<decltype(Method)>::Owner;
  const Owner* owner = held<Owner>(self);
  return owner ? read((owner->*Method)(), self) : nullptr;
}

/// cls.name() for a const method without arguments returning a number, without pybind11's
/// dispatch (RRCoord.x(): read for every obstacle every tick).
template <auto Method, typename Class>
void getter_method(Class& cls, const char* name, const char* doc = nullptr) {
  static PyMethodDef def{name, &call_getter<Method>, METH_NOARGS, doc};
  PyObject* descriptor = PyDescr_NewMethod(reinterpret_cast<PyTypeObject*>(cls.ptr()), &def);
  if (!descriptor) throw pybind11::error_already_set();
  cls.attr(name) = pybind11::reinterpret_steal<pybind11::object>(descriptor);
}

/// pybind11's == and != of a scoped enum (true when both are the same enum type with the same
/// value; an int or another enum is never equal) as C methods: a behaviour compares the game
/// state every tick, and pybind11's own calls __int__ through its dispatch twice per compare.
template <typename Enum, bool equal>
PyObject* enum_compare(PyObject* self, PyObject* other) {
  if (Py_TYPE(self) != Py_TYPE(other)) return PyBool_FromLong(!equal);
  const Enum* a = held<Enum>(self);
  const Enum* b = a ? held<Enum>(other) : nullptr;
  if (!b) return nullptr;
  return PyBool_FromLong((*a == *b) == equal);
}

template <typename Enum>
void fast_compare(pybind11::enum_<Enum>& cls) {
  static PyMethodDef eq{"__eq__", reinterpret_cast<PyCFunction>(&enum_compare<Enum, true>), METH_O, nullptr};
  static PyMethodDef ne{"__ne__", reinterpret_cast<PyCFunction>(&enum_compare<Enum, false>), METH_O, nullptr};
  for (PyMethodDef* def : {&eq, &ne}) {
    PyObject* descriptor = PyDescr_NewMethod(reinterpret_cast<PyTypeObject*>(cls.ptr()), def);
    if (!descriptor) throw pybind11::error_already_set();
    cls.attr(def->ml_name) = pybind11::reinterpret_steal<pybind11::object>(descriptor);
  }
}

} // namespace touchline::python::fast_fields

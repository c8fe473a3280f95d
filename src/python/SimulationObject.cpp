#include "python/SimulationObject.h"

#include <stdexcept>


namespace tabletop::python {

std::unique_lock<std::mutex> SimulationObject::lock() {
  if (owner_.load() == std::this_thread::get_id()) {
    throw std::runtime_error(
        "Simulation: called while another of its calls is running in this thread (from a signal handler?); "
        "call it once that returns");
  }
  std::unique_lock<std::mutex> held(mutex_, std::defer_lock);
  if (!held.try_lock()) {
    const pybind11::gil_scoped_release nogil;
    held.lock();
  }
  owner_.store(std::this_thread::get_id());
  return held;
}

SimulationObject::Use::Use(SimulationObject& object) : object_(object), lock_(object.lock()) {
  if (!object_.scene_) {
    object_.owner_.store(std::thread::id{});
    throw std::runtime_error("Simulation: closed; make a new one");
  }
}

SimulationObject::Use::~Use() { object_.owner_.store(std::thread::id{}); }

void SimulationObject::close() {
  std::unique_lock<std::mutex> held = lock();
  std::unique_ptr<SteppedScene> scene = std::move(scene_);
  owner_.store(std::thread::id{});
  held.unlock();
  const pybind11::gil_scoped_release nogil;  // a large world takes a while to free
  scene.reset();
}

bool SimulationObject::closed() {
  const std::unique_lock<std::mutex> held = lock();
  owner_.store(std::thread::id{});
  return !scene_;
}

pybind11::detail::value_and_holder valueAndHolder(const pybind11::handle& self) {
  const pybind11::detail::type_info* type = pybind11::detail::get_type_info(typeid(SimulationObject));
  if (!type || !PyObject_TypeCheck(self.ptr(), type->type)) {
    throw pybind11::type_error("expected a tabletop.Simulation as self");
  }
  return reinterpret_cast<pybind11::detail::instance*>(self.ptr())->get_value_and_holder(type);
}

SimulationObject& initialised(const pybind11::handle& self) {
  pybind11::detail::value_and_holder holder = valueAndHolder(self);
  if (!holder.holder_constructed()) {
    throw std::runtime_error("Simulation: not initialised (made by __new__, its __init__ never ran); make one with "
                             "tabletop.Simulation(scene)");
  }
  return *holder.value_ptr<SimulationObject>();
}

}  // namespace tabletop::python

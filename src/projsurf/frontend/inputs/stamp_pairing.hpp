#pragma once
// Pairing two streams by stamp, as a depth image goes with the camera_info of the same
// instant (the node, `detect --bag`): the latest few of one stream, looked up by stamp.
#include <cmath>
#include <cstddef>
#include <deque>
#include <utility>

namespace projsurf::frontend {

/// Stamps (s) equal within this are the same instant: ROS stamps are whole nanoseconds, as
/// doubles of a 1e9 s clock they keep about 0.1 us.
constexpr double kSameStampS = 1e-6;

template <class T>
class StampedBuffer {
public:
    /// Keeps the latest `capacity` values (30: one second of a 30 Hz camera).
    explicit StampedBuffer(std::size_t capacity = 30) : capacity_(capacity) {}

    void add(double stamp, T value) {
        items_.emplace_back(stamp, std::move(value));
        while (items_.size() > capacity_) items_.pop_front();
    }
    /// The value of this stamp, else nullptr.
    const T *exact(double stamp) const {
        for (auto it = items_.rbegin(); it != items_.rend(); ++it)
            if (std::abs(it->first - stamp) <= kSameStampS) return &it->second;
        return nullptr;
    }
    /// The value nearest in time (nullptr when empty); `found_stamp` is set to its stamp.
    const T *nearest(double stamp, double &found_stamp) const {
        const std::pair<double, T> *best = nullptr;
        for (const auto &item : items_)
            if (!best || std::abs(item.first - stamp) < std::abs(best->first - stamp)) best = &item;
        if (best) found_stamp = best->first;
        return best ? &best->second : nullptr;
    }
    bool empty() const { return items_.empty(); }

private:
    std::size_t capacity_;
    std::deque<std::pair<double, T>> items_;
};

}  // namespace projsurf::frontend

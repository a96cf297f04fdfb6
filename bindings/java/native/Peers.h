// One Java object per native M3G object (docs/java.md, "Identity and
// lifetime"). Each peer owns one reference to its object, through the
// `handle` field of Object3D; a table maps every object that has a peer to a
// weak reference to it, so a getter returns the same Java object for as long
// as the program can still see it. When the peer is collected, its Cleaner
// queues the handle; the reference is dropped on the next native call (on a
// thread that is calling m3g-vk, never on the Cleaner's), and the table entry
// goes with it unless a newer peer took its place.
#pragma once

#include <jni.h>

#include <m3g/Object3D.h>

namespace m3gjni {

/// Whether `object` has a live Java peer now.
bool hasLivePeer(JNIEnv* env, const m3g::Object3D* object);
/// Drops the references of collected peers (Object3D.release queued them).
void drainReleases(JNIEnv* env) noexcept;
/// Native objects with a Java peer, live or awaiting release (tests).
long peerCount() noexcept;

}  // namespace m3gjni

"use strict";(()=>{function Sa(n,e){return n!==null&&typeof n=="object"&&"$typeName"in n&&typeof n.$typeName=="string"?e===void 0?!0:e.typeName===n.$typeName:!1}var V;(function(n){n[n.DOUBLE=1]="DOUBLE",n[n.FLOAT=2]="FLOAT",n[n.INT64=3]="INT64",n[n.UINT64=4]="UINT64",n[n.INT32=5]="INT32",n[n.FIXED64=6]="FIXED64",n[n.FIXED32=7]="FIXED32",n[n.BOOL=8]="BOOL",n[n.STRING=9]="STRING",n[n.BYTES=12]="BYTES",n[n.UINT32=13]="UINT32",n[n.SFIXED32=15]="SFIXED32",n[n.SFIXED64=16]="SFIXED64",n[n.SINT32=17]="SINT32",n[n.SINT64=18]="SINT64"})(V||(V={}));function hg(){let n=this.buf,e=this.pos,t=0,i=0;for(let s=0;s<28;s+=7){let o=n[e++];if(t|=(o&127)<<s,(o&128)==0){this.pos=e,this.assertBounds(),this.varint64Lo=t,this.varint64Hi=i;return}}let r=n[e++];if(t|=(r&15)<<28,i=(r&112)>>4,(r&128)==0){this.pos=e,this.assertBounds(),this.varint64Lo=t,this.varint64Hi=i;return}for(let s=3;s<=31;s+=7){let o=n[e++];if(i|=(o&127)<<s,(o&128)==0){this.pos=e,this.assertBounds(),this.varint64Lo=t,this.varint64Hi=i;return}}throw new Error("invalid varint")}var Yl=4294967296;function Sf(n){let e=n[0]==="-";e&&(n=n.slice(1));let t=1e6,i=0,r=0;function s(o,a){let l=Number(n.slice(o,a));r*=t,i=i*t+l,i>=Yl&&(r=r+(i/Yl|0),i=i%Yl)}return s(-24,-18),s(-18,-12),s(-12,-6),s(-6),e?dg(i,r):Mf(i,r)}function fg(n,e){let t=Mf(n,e),i=t.hi&2147483648;i&&(t=dg(t.lo,t.hi));let r=Ef(t.lo,t.hi);return i?"-"+r:r}function Ef(n,e){if({lo:n,hi:e}=wS(n,e),e<=2097151)return String(Yl*e+n);let t=n&16777215,i=(n>>>24|e<<8)&16777215,r=e>>16&65535,s=t+i*6777216+r*6710656,o=i+r*8147497,a=r*2,l=1e7;return s>=l&&(o+=Math.floor(s/l),s%=l),o>=l&&(a+=Math.floor(o/l),o%=l),a.toString()+ug(o)+ug(s)}function wS(n,e){return{lo:n>>>0,hi:e>>>0}}function Mf(n,e){return{lo:n|0,hi:e|0}}function dg(n,e){return e=~e,n?n=~n+1:e+=1,Mf(n,e)}var ug=n=>{let e=String(n);return"0000000".slice(e.length)+e};function pg(n,e){if(n>>>0<128){e.push(n);return}if(n>=0){for(;n>127;)e.push(n&127|128),n=n>>>7;e.push(n)}else{for(let t=0;t<9;t++)e.push(n&127|128),n=n>>7;e.push(1)}}function mg(){let n=this.buf[this.pos++];if((n&128)===0)return this.assertBounds(),n;let e=n&127;if(n=this.buf[this.pos++],e|=(n&127)<<7,(n&128)===0)return this.assertBounds(),e;if(n=this.buf[this.pos++],e|=(n&127)<<14,(n&128)===0)return this.assertBounds(),e;if(n=this.buf[this.pos++],e|=(n&127)<<21,(n&128)===0)return this.assertBounds(),e;n=this.buf[this.pos++],e|=(n&15)<<28;for(let t=5;(n&128)!==0&&t<10;t++)n=this.buf[this.pos++];if((n&128)!==0)throw new Error("invalid varint");return this.assertBounds(),e>>>0}var Et=TS();function TS(){let n=new DataView(new ArrayBuffer(8));if(typeof BigInt=="function"&&typeof n.getBigInt64=="function"&&typeof n.getBigUint64=="function"&&typeof n.setBigInt64=="function"&&typeof n.setBigUint64=="function"&&(!!globalThis.Deno||!!globalThis.Bun||typeof process!="object"||typeof process.env!="object"||process.env.BUF_BIGINT_DISABLE!=="1")){let t=BigInt("-9223372036854775808"),i=BigInt("9223372036854775807"),r=BigInt("0"),s=BigInt("18446744073709551615");return{zero:BigInt(0),supported:!0,parse(o){let a=typeof o=="bigint"?o:BigInt(o);if(a>i||a<t)throw new Error(`invalid int64: ${o}`);return a},uParse(o){let a=typeof o=="bigint"?o:BigInt(o);if(a>s||a<r)throw new Error(`invalid uint64: ${o}`);return a},enc(o){return n.setBigInt64(0,this.parse(o),!0),{lo:n.getInt32(0,!0),hi:n.getInt32(4,!0)}},uEnc(o){return n.setBigInt64(0,this.uParse(o),!0),{lo:n.getInt32(0,!0),hi:n.getInt32(4,!0)}},dec(o,a){return n.setInt32(0,o,!0),n.setInt32(4,a,!0),n.getBigInt64(0,!0)},uDec(o,a){return n.setInt32(0,o,!0),n.setInt32(4,a,!0),n.getBigUint64(0,!0)}}}return{zero:"0",supported:!1,parse(t){return typeof t!="string"&&(t=t.toString()),gg(t),t},uParse(t){return typeof t!="string"&&(t=t.toString()),_g(t),t},enc(t){return typeof t!="string"&&(t=t.toString()),gg(t),Sf(t)},uEnc(t){return typeof t!="string"&&(t=t.toString()),_g(t),Sf(t)},dec(t,i){return fg(t,i)},uDec(t,i){return Ef(t,i)}}}function gg(n){if(!/^-?[0-9]+$/.test(n))throw new Error("invalid int64: "+n)}function _g(n){if(!/^[0-9]+$/.test(n))throw new Error("invalid uint64: "+n)}function Zn(n,e){switch(n){case V.STRING:return"";case V.BOOL:return!1;case V.DOUBLE:case V.FLOAT:return 0;case V.INT64:case V.UINT64:case V.SFIXED64:case V.FIXED64:case V.SINT64:return e?"0":Et.zero;case V.BYTES:return new Uint8Array(0);default:return 0}}function yg(n,e){switch(n){case V.BOOL:return e===!1;case V.STRING:return e==="";case V.BYTES:return e instanceof Uint8Array&&!e.byteLength;case V.DOUBLE:case V.FLOAT:return Object.is(e,0);default:return e==0}}var xg=2,Tn=Symbol.for("reflect unsafe local");function bg(n,e){let t=n[e.localName].case;return t===void 0?t:e.fields.find(i=>i.localName===t)}function vg(n,e){let t=e.localName;if(e.oneof)return n[e.oneof.localName].case===t;if(e.presence!=xg)return n[t]!==void 0&&Object.prototype.hasOwnProperty.call(n,t);switch(e.fieldKind){case"list":return n[t].length>0;case"map":return Object.keys(n[t]).length>0;case"scalar":return!yg(e.scalar,n[t]);case"enum":return n[t]!==e.enum.values[0].number}throw new Error("message field with implicit presence")}function ws(n,e){return Object.prototype.hasOwnProperty.call(n,e)&&n[e]!==void 0}function Sg(n,e){if(e.oneof){let t=n[e.oneof.localName];return t.case===e.localName?t.value:void 0}return n[e.localName]}function Eg(n,e,t){e.oneof?n[e.oneof.localName]={case:e.localName,value:t}:n[e.localName]=t}function Hn(n,e,t){e==="__proto__"?Object.defineProperty(n,"__proto__",{value:t,writable:!0,enumerable:!0,configurable:!0}):n[e]=t}function Mg(n,e){return Object.prototype.hasOwnProperty.call(n,e)?n[e]:void 0}function wg(n,e){let t=e.localName;if(e.oneof){let i=e.oneof.localName;n[i].case===t&&(n[i]={case:void 0})}else if(e.presence!=xg)delete n[t];else switch(e.fieldKind){case"map":n[t]={};break;case"list":n[t]=[];break;case"enum":n[t]=e.enum.values[0].number;break;case"scalar":n[t]=Zn(e.scalar,e.longAsString);break}}function Gi(n){return n!==null&&typeof n=="object"&&!Array.isArray(n)}function Ea(n,e){var t,i,r,s;if(Gi(n)&&Tn in n&&"add"in n&&"field"in n&&typeof n.field=="function"){if(e!==void 0){let o=e,a=n.field();return o.listKind==a.listKind&&o.scalar===a.scalar&&((t=o.message)===null||t===void 0?void 0:t.typeName)===((i=a.message)===null||i===void 0?void 0:i.typeName)&&((r=o.enum)===null||r===void 0?void 0:r.typeName)===((s=a.enum)===null||s===void 0?void 0:s.typeName)}return!0}return!1}function Ma(n,e){var t,i,r,s;if(Gi(n)&&Tn in n&&"has"in n&&"field"in n&&typeof n.field=="function"){if(e!==void 0){let o=e,a=n.field();return o.mapKey===a.mapKey&&o.mapKind==a.mapKind&&o.scalar===a.scalar&&((t=o.message)===null||t===void 0?void 0:t.typeName)===((i=a.message)===null||i===void 0?void 0:i.typeName)&&((r=o.enum)===null||r===void 0?void 0:r.typeName)===((s=a.enum)===null||s===void 0?void 0:s.typeName)}return!0}return!1}function wa(n,e){return Gi(n)&&Tn in n&&"desc"in n&&Gi(n.desc)&&n.desc.kind==="message"&&(e===void 0||n.desc.typeName==e.typeName)}function Tg(n){return Ag(n.$typeName)}function mi(n){let e=n.fields[0];return Ag(n.typeName)&&e!==void 0&&e.fieldKind=="scalar"&&e.name=="value"&&e.number==1}function Zl(n){switch(n.typeName){case"google.protobuf.Any":case"google.protobuf.Timestamp":case"google.protobuf.Duration":case"google.protobuf.FieldMask":case"google.protobuf.Struct":case"google.protobuf.Value":case"google.protobuf.ListValue":return!0;default:return mi(n)}}var AS=new Set(["google.protobuf.DoubleValue","google.protobuf.FloatValue","google.protobuf.Int64Value","google.protobuf.UInt64Value","google.protobuf.Int32Value","google.protobuf.UInt32Value","google.protobuf.BoolValue","google.protobuf.StringValue","google.protobuf.BytesValue"]);function Ag(n){return AS.has(n)}var RS=999,IS=998,Ig=2;function xt(n,e){return Sa(e,n)?e:Cg(n)(e)}var Rg=new WeakMap;function Cg(n){let e=Rg.get(n);return e===void 0&&(e=CS(n),Rg.set(n,e)),e}var wf=0,Ng=1,Pg=2,Lg=3;function CS(n){let e=n.typeName,{properties:t,prototype:i}=NS(n);return r=>{let s;i!==void 0?(s=Object.create(i),s.$typeName=e):s={$typeName:e};for(let o=0;o<t.length;o++){let a=t[o],l=a.name,c=r?.[l];switch(a.kind){case wf:c!=null?s[l]=a.convert!==void 0?a.convert(c):c:a.constant!==void 0&&(s[l]=a.constant);break;case Ng:s[l]=a.convert!==void 0&&Array.isArray(c)?c.map(a.convert):c??[];break;case Pg:if(a.convert===void 0||!Gi(c))s[l]=c??{};else{let u={},h=Object.keys(c);for(let f=0;f<h.length;f++)Hn(u,h[f],a.convert(c[h[f]]));s[l]=u}break;case Lg:{let u=c;if(u?.case!=null){let h=a.convert.get(u.case);if(h!==void 0){s[l]={case:u.case,value:h(u.value)};break}}s[l]={case:void 0};break}}}return s}}function NS(n){var e,t;let i=[],r={},s=LS(n);for(let o of n.members){let a=o.localName;if(o.kind=="oneof"){i.push({name:a,kind:Lg,constant:void 0,convert:PS(o)});continue}switch(o.fieldKind){case"message":{i.push({name:a,kind:wf,constant:void 0,convert:Kl(o)});break}case"list":{i.push({name:a,kind:Ng,constant:void 0,convert:o.listKind=="message"?(e=Kl(o))!==null&&e!==void 0?e:(l=>l):o.scalar==V.BYTES?Ta:void 0});break}case"map":{i.push({name:a,kind:Pg,constant:void 0,convert:o.mapKind=="message"?(t=Kl(o))!==null&&t!==void 0?t:(l=>l):o.scalar==V.BYTES?Ta:void 0});break}default:{let l=DS(o);i.push({name:a,kind:wf,constant:o.presence==Ig?l:void 0,convert:o.fieldKind=="scalar"&&o.scalar==V.BYTES?Ta:void 0}),s&&(r[a]=l);break}}}return{properties:i,prototype:s?r:void 0}}function PS(n){let e=new Map;for(let t of n.fields){let i;t.fieldKind=="message"?i=Kl(t):t.fieldKind=="scalar"&&t.scalar==V.BYTES&&(i=Ta),e.set(t.localName,i??(r=>r))}return e}function Kl(n){if(n.fieldKind=="message"&&!n.oneof&&mi(n.message))return n.message.fields[0].scalar==V.BYTES?Ta:void 0;if(n.message.typeName=="google.protobuf.Struct"&&n.parent.typeName!=="google.protobuf.Value")return;let e=n.message,t;return i=>!Gi(i)||Sa(i,e)?i:(t??(t=Cg(e)),t(i))}function Ta(n){return Array.isArray(n)?new Uint8Array(n):n}function LS(n){switch(n.file.edition){case RS:return!1;case IS:return!0;default:return n.fields.some(e=>e.presence!=Ig&&e.fieldKind!="message"&&!e.oneof)}}function DS(n){let e=n.getDefaultValue();return e!==void 0?n.fieldKind=="scalar"&&n.longAsString?e.toString():e:n.fieldKind=="scalar"?Zn(n.scalar,n.longAsString):n.enum.values[0].number}var FS=["FieldValueInvalidError","FieldListRangeError","ForeignFieldError"],Mt=class extends Error{constructor(e,t,i="FieldValueInvalidError"){super(t),this.name=i,this.field=()=>e}};function Dg(n){return n instanceof Error&&FS.includes(n.name)&&"field"in n&&typeof n.field=="function"}var Tf;function US(n){var e;Tf=Object.assign(Object.assign({},n),{encodeUtf8Into:(e=n.encodeUtf8Into)!==null&&e!==void 0?e:Af(n.encodeUtf8.bind(n))})}function Aa(){if(!Tf){let n=globalThis;if(!n.TextEncoder||!n.TextDecoder)throw new Error("encoding API missing: install TextEncoder and TextDecoder on globalThis");let e=new n.TextEncoder,t=new n.TextDecoder("utf-8",{ignoreBOM:!0}),i,r={encodeUtf8(o){return e.encode(o)},decodeUtf8(o,a){return a?(i||(i=new n.TextDecoder("utf-8",{fatal:!0,ignoreBOM:!0})),i.decode(o)):t.decode(o)},checkUtf8(o){try{return encodeURIComponent(o),!0}catch{return!1}}};e.encodeInto&&(r.encodeUtf8Into=e.encodeInto.bind(e));let s=String.prototype.isWellFormed;s&&(r.checkUtf8=o=>s.call(o)),US(r)}return Tf}function Af(n){return(e,t)=>{let i=n(e);return t.set(i),{written:i.byteLength}}}var Gt;(function(n){n[n.Varint=0]="Varint",n[n.Bit64=1]="Bit64",n[n.LengthDelimited=2]="LengthDelimited",n[n.StartGroup=3]="StartGroup",n[n.EndGroup=4]="EndGroup",n[n.Bit32=5]="Bit32"})(Gt||(Gt={}));var Cf=4294967295,Nf=2147483647,Pf=-2147483648,ro=class{constructor(e){this.stackPos=[],this.encodeUtf8Into=e?Af(e):Aa().encodeUtf8Into,this.buffer=Ug,this.viewCache=BS,this.pos=0}ensureCapacity(e){let t=this.pos+e;if(t>this.buffer.length){let i=this.buffer.length||OS;for(;i<t;)i*=2;let r=new Uint8Array(i);this.pos>0&&r.set(this.buffer),this.buffer=r}}view(){let e=this.buffer,t=this.viewCache;if(t.byteLength===e.byteLength)return t;let i=new DataView(e.buffer);return this.viewCache=i,i}finish(){let e=this.buffer.slice(0,this.pos);return this.pos=0,this.stackPos=[],e}fork(){return this.stackPos.push(this.pos),this.ensureCapacity(Ra),this.buffer[this.pos++]=0,this}join(){let e=this.stackPos.pop();if(e===void 0)throw new Error("invalid state, fork stack empty");let t=this.pos-e-Ra,i=Rf(t);return i>Ra&&(this.ensureCapacity(i-Ra),this.buffer.copyWithin(e+i,e+Ra,this.pos)),this.pos=e,this.uint32(t),this.pos+=t,this}tag(e,t){return this.uint32((e<<3|t)>>>0)}raw(e){return this.ensureCapacity(e.length),this.buffer.set(e,this.pos),this.pos+=e.length,this}uint32(e){if(Fg(e),this.ensureCapacity(5),e<128)return this.buffer[this.pos++]=e,this;for(;e>127;)this.buffer[this.pos++]=e&127|128,e>>>=7;return this.buffer[this.pos++]=e,this}int32(e){if(If(e),e>=0)return this.uint32(e);this.ensureCapacity(10);for(let t=0;t<9;t++)this.buffer[this.pos++]=e&127|128,e>>=7;return this.buffer[this.pos++]=1,this}bool(e){return this.ensureCapacity(1),this.buffer[this.pos++]=e?1:0,this}bytes(e){return this.uint32(e.byteLength),this.raw(e)}string(e){typeof e!="string"&&(e=String(e));let t=e.length;if(t<=Og){this.ensureCapacity(t+1);let l=this.buffer,c=this.pos;l[c++]=t;let u=0;for(;u<t;u++){let h=e.charCodeAt(u);if(h>127)break;l[c++]=h}if(u==t)return this.pos=c,this}this.ensureCapacity(t*3+5);let i=Rf(t),r=this.buffer,s=this.pos,{written:o}=this.encodeUtf8Into(e,r.subarray(s+i)),a=Rf(o);return a!=i&&r.copyWithin(s+a,s+i,s+i+o),this.uint32(o),this.pos+=o,this}float(e){return kS(e),this.ensureCapacity(4),this.view().setFloat32(this.pos,e,!0),this.pos+=4,this}double(e){return this.ensureCapacity(8),this.view().setFloat64(this.pos,e,!0),this.pos+=8,this}fixed32(e){return Fg(e),this.ensureCapacity(4),this.view().setUint32(this.pos,e,!0),this.pos+=4,this}sfixed32(e){return If(e),this.ensureCapacity(4),this.view().setInt32(this.pos,e,!0),this.pos+=4,this}sint32(e){return If(e),this.uint32((e<<1^e>>31)>>>0)}sfixed64(e){let t=Et.enc(e);this.ensureCapacity(8);let i=this.view();return i.setInt32(this.pos,t.lo,!0),i.setInt32(this.pos+4,t.hi,!0),this.pos+=8,this}fixed64(e){let t=Et.uEnc(e);this.ensureCapacity(8);let i=this.view();return i.setInt32(this.pos,t.lo,!0),i.setInt32(this.pos+4,t.hi,!0),this.pos+=8,this}int64(e){let t=Et.enc(e);return this.writeVarint64(t.lo,t.hi)}sint64(e){let t=Et.enc(e),i=t.hi>>31,r=t.lo<<1^i,s=(t.hi<<1|t.lo>>>31)^i;return this.writeVarint64(r,s)}uint64(e){let t=Et.uEnc(e);return this.writeVarint64(t.lo,t.hi)}writeVarint64(e,t){this.ensureCapacity(10);let i=this.buffer,r=this.pos;for(let a=0;a<28;a=a+7){let l=e>>>a,c=!(!(l>>>7)&&t==0);if(i[r++]=(c?l|128:l)&255,!c)return this.pos=r,this}let s=e>>>28&15|(t&7)<<4,o=t>>3!=0;if(i[r++]=(o?s|128:s)&255,!o)return this.pos=r,this;for(let a=3;a<31;a=a+7){let l=t>>>a,c=!!(l>>>7);if(i[r++]=(c?l|128:l)&255,!c)return this.pos=r,this}return i[r++]=t>>>31&1,this.pos=r,this}},OS=128,Ra=1,Ug=new Uint8Array(0),BS=new DataView(Ug.buffer),Og=32;function Rf(n){return n<128?1:n<16384?2:n<2097152?3:n<268435456?4:5}var ur=class{constructor(e,t=Aa().decodeUtf8){this.decodeUtf8=t,this.varint64Lo=0,this.varint64Hi=0,this.varint64=hg,this.uint32=mg,this.buf=e,this.len=e.length,this.pos=0,this.view=new DataView(e.buffer,e.byteOffset,e.byteLength)}tag(){let e=this.pos,t=this.uint32(),i=this.pos-e;if(i>5||i==5&&this.buf[this.pos-1]>15)throw new Error("illegal tag: varint overflows uint32");let r=t>>>3,s=t&7;if(r<=0||s>5)throw new Error("illegal tag: field no "+r+" wire type "+s);return[r,s]}skip(e,t,i=100){let r=this.pos;switch(e){case Gt.Varint:for(;this.buf[this.pos++]&128;);break;case Gt.Bit64:this.pos+=4;case Gt.Bit32:this.pos+=4;break;case Gt.LengthDelimited:let s=this.uint32();this.pos+=s;break;case Gt.StartGroup:if(i<=0)throw new Error("maximum recursion depth reached");for(;;){let[o,a]=this.tag();if(a===Gt.EndGroup){if(t!==void 0&&o!==t)throw new Error("invalid end group tag");break}this.skip(a,o,i-1)}break;default:throw new Error("cant skip wire type "+e)}return this.assertBounds(),this.buf.subarray(r,this.pos)}assertBounds(){if(this.pos>this.len)throw new RangeError("premature EOF")}int32(){return this.uint32()|0}sint32(){let e=this.uint32();return e>>>1^-(e&1)}int64(){return this.varint64(),Et.dec(this.varint64Lo,this.varint64Hi)}uint64(){return this.varint64(),Et.uDec(this.varint64Lo,this.varint64Hi)}sint64(){this.varint64();let e=this.varint64Lo,t=this.varint64Hi,i=-(e&1);return e=(e>>>1|(t&1)<<31)^i,t=t>>>1^i,Et.dec(e,t)}bool(){let e=this.buf[this.pos];return e<128?(this.pos++,e!==0):(this.varint64(),this.varint64Lo!==0||this.varint64Hi!==0)}fixed32(){return this.view.getUint32((this.pos+=4)-4,!0)}sfixed32(){return this.view.getInt32((this.pos+=4)-4,!0)}fixed64(){return Et.uDec(this.sfixed32(),this.sfixed32())}sfixed64(){return Et.dec(this.sfixed32(),this.sfixed32())}float(){return this.view.getFloat32((this.pos+=4)-4,!0)}double(){return this.view.getFloat64((this.pos+=8)-8,!0)}bytes(){let e=this.uint32(),t=this.pos;return this.pos+=e,this.assertBounds(),this.buf.subarray(t,t+e)}string(e){let t=this.uint32(),i=this.pos;this.pos+=t,this.assertBounds();let r=this.buf;if(t<=Og){let s=new Array(t);for(let o=0;o<t;o++){let a=r[i+o];if(a>127)return this.decodeUtf8(r.subarray(i,this.pos),e);s[o]=a}return String.fromCharCode.apply(String,s)}return this.decodeUtf8(r.subarray(i,this.pos),e)}};function If(n){if(typeof n=="string")n=Number(n);else if(typeof n!="number")throw new Error("invalid int32: "+typeof n);if(!Number.isInteger(n)||n>Nf||n<Pf)throw new Error("invalid int32: "+n)}function Fg(n){if(typeof n=="string")n=Number(n);else if(typeof n!="number")throw new Error("invalid uint32: "+typeof n);if(!Number.isInteger(n)||n>Cf||n<0)throw new Error("invalid uint32: "+n)}function kS(n){if(typeof n=="string"){let e=n;if(n=Number(n),Number.isNaN(n)&&e!=="NaN")throw new Error("invalid float32: "+e)}else if(typeof n!="number")throw new Error("invalid float32: "+typeof n);if(!Number.isFinite(Math.fround(n))&&Number.isFinite(n))throw new Error("invalid float32: "+n)}function $l(n,e){let t=n.fieldKind=="list"?Ea(e,n):n.fieldKind=="map"?Ma(e,n):Df(n,e);if(t===!0)return;let i;switch(n.fieldKind){case"list":i=`expected ${Vg(n)}, got ${pn(e)}`;break;case"map":i=`expected ${Gg(n)}, got ${pn(e)}`;break;default:i=Ci(n,e,t)}return new Mt(n,i)}function Lf(n,e,t){let i=Df(n,t);if(i!==!0)return new Mt(n,`list item #${e+1}: ${Ci(n,t,i)}`)}function Bg(n,e,t){let i=Ar(n.mapKey)(e);if(i!==!0)return new Mt(n,`invalid map key: ${Ci({scalar:n.mapKey},e,i)}`);let r=Df(n,t);if(r!==!0)return new Mt(n,`map entry ${pn(e)}: ${Ci(n,t,r)}`)}function Df(n,e){return n.scalar!==void 0?Ar(n.scalar)(e):n.enum!==void 0?n.enum.open?Ar(V.INT32)(e):n.enum.values.some(t=>t.number===e):wa(e,n.message)}function Ar(n){switch(n){case V.DOUBLE:return e=>typeof e=="number";case V.FLOAT:return e=>typeof e!="number"?!1:!Number.isFinite(Math.fround(e))&&Number.isFinite(e)?`${e.toFixed()} out of range`:!0;case V.INT32:case V.SFIXED32:case V.SINT32:return e=>typeof e!="number"||!Number.isInteger(e)?!1:e>Nf||e<Pf?`${e.toFixed()} out of range`:!0;case V.FIXED32:case V.UINT32:return e=>typeof e!="number"||!Number.isInteger(e)?!1:e>Cf||e<0?`${e.toFixed()} out of range`:!0;case V.BOOL:return e=>typeof e=="boolean";case V.STRING:return e=>typeof e!="string"?!1:Aa().checkUtf8(e)||"invalid UTF8";case V.BYTES:return e=>e instanceof Uint8Array;case V.INT64:case V.SFIXED64:case V.SINT64:return e=>{if(typeof e=="bigint"||typeof e=="number"||typeof e=="string"&&e.length>0)try{return Et.parse(e),!0}catch{return`${e} out of range`}return!1};case V.FIXED64:case V.UINT64:return e=>{if(typeof e=="bigint"||typeof e=="number"||typeof e=="string"&&e.length>0)try{return Et.uParse(e),!0}catch{return`${e} out of range`}return!1}}}function Ci(n,e,t){return t=typeof t=="string"?`: ${t}`:`, got ${pn(e)}`,n.scalar!==void 0?`expected ${VS(n.scalar)}`+t:n.enum!==void 0?`expected ${n.enum.toString()}`+t:`expected ${kg(n.message)}`+t}function pn(n){switch(typeof n){case"object":return n===null?"null":n instanceof Uint8Array?`Uint8Array(${n.length})`:Array.isArray(n)?`Array(${n.length})`:Ea(n)?Vg(n.field()):Ma(n)?Gg(n.field()):wa(n)?kg(n.desc):Sa(n)?`message ${n.$typeName}`:"object";case"string":return n.length>30?"string":`"${n.split('"').join('\\"')}"`;case"boolean":return String(n);case"number":return String(n);case"bigint":return String(n)+"n";default:return typeof n}}function kg(n){return`ReflectMessage (${n.typeName})`}function Vg(n){switch(n.listKind){case"message":return`ReflectList (${n.message.toString()})`;case"enum":return`ReflectList (${n.enum.toString()})`;case"scalar":return`ReflectList (${V[n.scalar]})`}}function Gg(n){switch(n.mapKind){case"message":return`ReflectMap (${V[n.mapKey]}, ${n.message.toString()})`;case"enum":return`ReflectMap (${V[n.mapKey]}, ${n.enum.toString()})`;case"scalar":return`ReflectMap (${V[n.mapKey]}, ${V[n.scalar]})`}}function VS(n){switch(n){case V.STRING:return"string";case V.BOOL:return"boolean";case V.INT64:case V.SINT64:case V.SFIXED64:return"bigint (int64)";case V.UINT64:case V.FIXED64:return"bigint (uint64)";case V.BYTES:return"Uint8Array";case V.DOUBLE:return"number (float64)";case V.FLOAT:return"number (float32)";case V.FIXED32:case V.UINT32:return"number (uint32)";case V.INT32:case V.SFIXED32:case V.SINT32:return"number (int32)"}}var GS=0;function oi(n){if(zS(n))return{toMessage:t=>ql(t),toLocal:t=>Jl(t)};if(n.fieldKind=="message"&&!n.oneof&&mi(n.message)){let t=n.message,i=t.fields[0].localName;return{toMessage:r=>{let s=xt(t);return r!==void 0&&(s[i]=r),s},toLocal:r=>r[i]}}let e=n.message;return{toMessage:t=>t===void 0?xt(e):t,toLocal:t=>t}}function zS(n){return n.message.typeName=="google.protobuf.Struct"&&n.parent.typeName!="google.protobuf.Value"}function ql(n){let e={$typeName:"google.protobuf.Struct",fields:{}};if(Gi(n))for(let t of Object.keys(n))Hn(e.fields,t,Hg(n[t]));return e}function Jl(n){let e={};for(let t of Object.keys(n.fields))Hn(e,t,zg(n.fields[t]));return e}function zg(n){switch(n.kind.case){case"structValue":return Jl(n.kind.value);case"listValue":return n.kind.value.values.map(zg);case"nullValue":case void 0:return null;default:return n.kind.value}}function Hg(n){let e={$typeName:"google.protobuf.Value",kind:{case:void 0}};switch(typeof n){case"number":e.kind={case:"numberValue",value:n};break;case"string":e.kind={case:"stringValue",value:n};break;case"boolean":e.kind={case:"boolValue",value:n};break;case"object":if(n===null)e.kind={case:"nullValue",value:GS};else if(Array.isArray(n)){let t={$typeName:"google.protobuf.ListValue",values:[]};if(Array.isArray(n))for(let i of n)t.values.push(Hg(i));e.kind={case:"listValue",value:t}}else e.kind={case:"structValue",value:ql(n)};break}return e}function Zg(n,e,t=!0){return new Ql(n,e,t)}var Wg=new WeakMap,Ql=class{get sortedFields(){let e=Wg.get(this.desc);if(e)return e;let t=this.desc.fields.concat().sort((i,r)=>i.number-r.number);return Wg.set(this.desc,t),t}constructor(e,t,i=!0){this.lists=new Map,this.maps=new Map,this.check=i,this.desc=e,this.message=this[Tn]=t??xt(e),this.fields=e.fields,this.oneofs=e.oneofs,this.members=e.members}findNumber(e){return this._fieldsByNumber||(this._fieldsByNumber=new Map(this.desc.fields.map(t=>[t.number,t]))),this._fieldsByNumber.get(e)}oneofCase(e){return Ia(this.message,e),bg(this.message,e)}isSet(e){return Ia(this.message,e),vg(this.message,e)}clear(e){Ia(this.message,e),wg(this.message,e)}get(e){Ia(this.message,e);let t=Sg(this.message,e);switch(e.fieldKind){case"list":let i=this.lists.get(e);return(!i||i[Tn]!==t)&&this.lists.set(e,i=new Of(e,t,this.check)),i;case"map":let r=this.maps.get(e);return(!r||r[Tn]!==t)&&this.maps.set(e,r=new Bf(e,t,this.check)),r;case"message":return Vf(e,t,this.check);case"scalar":return t===void 0?Zn(e.scalar,!1):Gf(e,t);case"enum":return t??e.enum.values[0].number}}set(e,t){if(Ia(this.message,e),this.check){let r=$l(e,t);if(r)throw r}let i;e.fieldKind=="message"?i=kf(e,t):Ma(t)||Ea(t)?i=t[Tn]:i=zf(e,t),Eg(this.message,e,i)}getUnknown(){return this.message.$unknown}setUnknown(e){this.message.$unknown=e}};function Ia(n,e){if(e.parent.typeName!==n.$typeName)throw new Mt(e,`cannot use ${e.toString()} with message ${n.$typeName}`,"ForeignFieldError")}var Of=class{field(){return this._field}get size(){return this._arr.length}constructor(e,t,i){this._field=e,this._arr=this[Tn]=t,this.check=i}get(e){let t=this._arr[e];return t===void 0?void 0:Ff(this._field,t,this.check)}set(e,t){if(e<0||e>=this._arr.length)throw new Mt(this._field,`list item #${e+1}: out of range`);if(this.check){let i=Lf(this._field,e,t);if(i)throw i}this._arr[e]=Xg(this._field,t)}add(e){if(this.check){let t=Lf(this._field,this._arr.length,e);if(t)throw t}this._arr.push(Xg(this._field,e))}clear(){this._arr.splice(0,this._arr.length)}[Symbol.iterator](){return this.values()}keys(){return this._arr.keys()}*values(){for(let e of this._arr)yield Ff(this._field,e,this.check)}*entries(){for(let e=0;e<this._arr.length;e++)yield[e,Ff(this._field,this._arr[e],this.check)]}};var Bf=class{constructor(e,t,i=!0){this.obj=this[Tn]=t??{},this.check=i,this._field=e}field(){return this._field}set(e,t){if(this.check){let i=Bg(this._field,e,t);if(i)throw i}return Hn(this.obj,jl(e),HS(this._field,t)),this}delete(e){let t=jl(e),i=Object.prototype.hasOwnProperty.call(this.obj,t);return i&&delete this.obj[t],i}clear(){for(let e of Object.keys(this.obj))delete this.obj[e]}get(e){let t=Mg(this.obj,jl(e));return t!==void 0&&(t=Uf(this._field,t,this.check)),t}has(e){return Object.prototype.hasOwnProperty.call(this.obj,jl(e))}*keys(){for(let e of Object.keys(this.obj))yield Yg(e,this._field.mapKey)}*entries(){for(let e of Object.entries(this.obj))yield[Yg(e[0],this._field.mapKey),Uf(this._field,e[1],this.check)]}[Symbol.iterator](){return this.entries()}get size(){return Object.keys(this.obj).length}*values(){for(let e of Object.values(this.obj))yield Uf(this._field,e,this.check)}forEach(e,t){for(let i of this.entries())e.call(t,i[1],i[0],this)}};function kf(n,e){return wa(e)?Tg(e.message)&&!n.oneof&&n.fieldKind=="message"?e.message.value:e.desc.typeName=="google.protobuf.Struct"&&n.parent.typeName!="google.protobuf.Value"?Jl(e.message):e.message:e}function Vf(n,e,t){return e!==void 0&&(mi(n.message)&&!n.oneof&&n.fieldKind=="message"?e={$typeName:n.message.typeName,value:Gf(n.message.fields[0],e)}:n.message.typeName=="google.protobuf.Struct"&&n.parent.typeName!="google.protobuf.Value"&&Gi(e)&&(e=ql(e))),new Ql(n.message,e,t)}function Xg(n,e){return n.listKind=="message"?kf(n,e):zf(n,e)}function Ff(n,e,t){return n.listKind=="message"?Vf(n,e,t):Gf(n,e)}function HS(n,e){return n.mapKind=="message"?kf(n,e):zf(n,e)}function Uf(n,e,t){return n.mapKind=="message"?Vf(n,e,t):e}function jl(n){return typeof n=="string"||typeof n=="number"?n:String(n)}function Yg(n,e){switch(e){case V.STRING:return n;case V.INT32:case V.FIXED32:case V.UINT32:case V.SFIXED32:case V.SINT32:{let t=Number.parseInt(n);if(Number.isFinite(t))return t;break}case V.BOOL:switch(n){case"true":return!0;case"false":return!1}break;case V.UINT64:case V.FIXED64:try{return Et.uParse(n)}catch{}break;default:try{return Et.parse(n)}catch{}break}return n}function Gf(n,e){switch(n.scalar){case V.INT64:case V.SFIXED64:case V.SINT64:"longAsString"in n&&n.longAsString&&typeof e=="string"&&(e=Et.parse(e));break;case V.FIXED64:case V.UINT64:"longAsString"in n&&n.longAsString&&typeof e=="string"&&(e=Et.uParse(e));break}return e}function zf(n,e){switch(n.scalar){case V.INT64:case V.SFIXED64:case V.SINT64:"longAsString"in n&&n.longAsString?e=String(e):(typeof e=="string"||typeof e=="number")&&(e=Et.parse(e));break;case V.FIXED64:case V.UINT64:"longAsString"in n&&n.longAsString?e=String(e):(typeof e=="string"||typeof e=="number")&&(e=Et.uParse(e));break}return e}var Kg=Uint8Array.prototype.setFromBase64;function oo(n){let e=n.length,t=e-(e+3>>2);(e&3)==0&&n[e-1]=="="&&(t-=n[e-2]=="="?2:1);let i=new Uint8Array(t),r=-1;if(Kg)try{let s=Kg.call(i,n);s.read==e&&(r=s.written)}catch{}return r<0&&(r=WS(i,n)),r==t?i:i.subarray(0,r)}function WS(n,e){let t=YS(),i=0,r=0,s,o=0;for(let a=0;a<e.length;a++){if(s=t[e.charCodeAt(a)],s===void 0)switch(e[a]){case"=":r=0;case`
`:case"\r":case"	":case" ":continue;default:throw Error("invalid base64 string")}switch(r){case 0:o=s,r=1;break;case 1:n[i++]=o<<2|(s&48)>>4,o=s,r=2;break;case 2:n[i++]=(o&15)<<4|(s&60)>>2,o=s,r=3;break;case 3:n[i++]=(o&3)<<6|s,r=0;break}}if(r==1)throw Error("invalid base64 string");return i}var $g=Uint8Array.prototype.toBase64,XS={std:{alphabet:"base64",omitPadding:!1},std_raw:{alphabet:"base64",omitPadding:!0},url:{alphabet:"base64url",omitPadding:!0}};function Hf(n,e="std"){if($g)return $g.call(n,XS[e]);let t=Jg(e),i=e=="std",r="",s=0,o,a=0;for(let l=0;l<n.length;l++)switch(o=n[l],s){case 0:r+=t[o>>2],a=(o&3)<<4,s=1;break;case 1:r+=t[a|o>>4],a=(o&15)<<2,s=2;break;case 2:r+=t[a|o>>6],r+=t[o&63],s=0;break}return s&&(r+=t[a],i&&(r+="=",s==1&&(r+="="))),r}var ec,qg,so;function Jg(n){return ec||(ec="ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/".split(""),qg=ec.slice(0,-2).concat("-","_")),n=="url"?qg:ec}function YS(){if(!so){so=[];let n=Jg("std");for(let e=0;e<n.length;e++)so[n[e].charCodeAt(0)]=e;so[45]=n.indexOf("+"),so[95]=n.indexOf("/")}return so}function Rr(n){let e=!1,t=[];for(let i=0;i<n.length;i++){let r=n.charAt(i);switch(r){case"_":e=!0;break;case"0":case"1":case"2":case"3":case"4":case"5":case"6":case"7":case"8":case"9":t.push(r),e=!1;break;default:e&&(e=!1,r=r.toUpperCase()),t.push(r);break}}return t.join("")}function tc(n){return n.replace(/[A-Z]/g,e=>"_"+e.toLowerCase())}var ZS=new Set(["constructor","toString","toJSON","valueOf"]);function ao(n){return ZS.has(n)?n+"$":n}function Ca(n){for(let e of n.field)ws(e,"jsonName")||(e.jsonName=Rr(e.name));n.nestedType.forEach(Ca)}function jg(n,e){let t=n.values.find(i=>i.name===e);if(!t)throw new Error(`cannot parse ${n} default value: ${e}`);return t.number}function Qg(n,e){switch(n){case V.STRING:return e;case V.BYTES:{let t=KS(e);if(t===!1)throw new Error(`cannot parse ${V[n]} default value: ${e}`);return t}case V.INT64:case V.SFIXED64:case V.SINT64:return Et.parse(e);case V.UINT64:case V.FIXED64:return Et.uParse(e);case V.DOUBLE:case V.FLOAT:switch(e){case"inf":return Number.POSITIVE_INFINITY;case"-inf":return Number.NEGATIVE_INFINITY;case"nan":return Number.NaN;default:return parseFloat(e)}case V.BOOL:return e==="true";case V.INT32:case V.UINT32:case V.SINT32:case V.FIXED32:case V.SFIXED32:return parseInt(e,10)}}function KS(n){let e=[],t={tail:n,c:"",next(){return this.tail.length==0?!1:(this.c=this.tail[0],this.tail=this.tail.substring(1),!0)},take(i){if(this.tail.length>=i){let r=this.tail.substring(0,i);return this.tail=this.tail.substring(i),r}return!1}};for(;t.next();)switch(t.c){case"\\":if(t.next())switch(t.c){case"\\":e.push(t.c.charCodeAt(0));break;case"b":e.push(8);break;case"f":e.push(12);break;case"n":e.push(10);break;case"r":e.push(13);break;case"t":e.push(9);break;case"v":e.push(11);break;case"0":case"1":case"2":case"3":case"4":case"5":case"6":case"7":{let i=t.c,r=t.take(2);if(r===!1)return!1;let s=parseInt(i+r,8);if(Number.isNaN(s))return!1;e.push(s);break}case"x":{let i=t.c,r=t.take(2);if(r===!1)return!1;let s=parseInt(i+r,16);if(Number.isNaN(s))return!1;e.push(s);break}case"u":{let i=t.c,r=t.take(4);if(r===!1)return!1;let s=parseInt(i+r,16);if(Number.isNaN(s))return!1;let o=new Uint8Array(4);new DataView(o.buffer).setInt32(0,s,!0),e.push(o[0],o[1],o[2],o[3]);break}case"U":{let i=t.c,r=t.take(8);if(r===!1)return!1;let s=Et.uEnc(i+r),o=new Uint8Array(8),a=new DataView(o.buffer);a.setInt32(0,s.lo,!0),a.setInt32(4,s.hi,!0),e.push(o[0],o[1],o[2],o[3],o[4],o[5],o[6],o[7]);break}}break;default:e.push(t.c.charCodeAt(0))}return new Uint8Array(e)}function*nc(n){switch(n.kind){case"file":for(let e of n.messages)yield e,yield*nc(e);yield*n.enums,yield*n.services,yield*n.extensions;break;case"message":for(let e of n.nestedMessages)yield e,yield*nc(e);yield*n.nestedEnums,yield*n.nestedExtensions;break}}function ic(n,e){return $S([n,e])}function $S(n,e){let t=qS();if(!n.length)return t;if("$typeName"in n[0]&&n[0].$typeName=="google.protobuf.FileDescriptorSet"){for(let i of n[0].file)e?.(i),i0(i,t);return t}if("$typeName"in n[0]){let o=function(a){let l=[];for(let c of a.dependency){if(t.getFile(c)!=null||s.has(c))continue;let u=r(c);if(!u)throw new Error(`Unable to resolve ${c}, imported by ${a.name}`);"kind"in u?t.addFile(u,!1,!0):(s.add(u.name),l.push(u))}return l.concat(...l.map(o))},i=n[0],r=n[1],s=new Set;for(let a of[i,...o(i)].reverse())e?.(a),i0(a,t)}else for(let i of n)for(let r of i.files)t.addFile(r);return t}function qS(){let n=new Map,e=new Map,t=new Map;return{kind:"registry",types:n,extendees:e,[Symbol.iterator](){return n.values()},get files(){return t.values()},addFile(i,r,s){if(t.set(i.proto.name,i),!r)for(let o of nc(i))this.add(o);if(s)for(let o of i.dependencies)this.addFile(o,r,s)},add(i){if(i.kind=="extension"){let r=e.get(i.extendee.typeName);r||e.set(i.extendee.typeName,r=new Map),r.set(i.number,i)}n.set(i.typeName,i)},get(i){return n.get(i)},getFile(i){return t.get(i)},getMessage(i){let r=n.get(i);return r?.kind=="message"?r:void 0},getEnum(i){let r=n.get(i);return r?.kind=="enum"?r:void 0},getExtension(i){let r=n.get(i);return r?.kind=="extension"?r:void 0},getExtensionFor(i,r){var s;return(s=e.get(i.typeName))===null||s===void 0?void 0:s.get(r)},getService(i){let r=n.get(i);return r?.kind=="service"?r:void 0}}}var JS=998,jS=999,QS=9999,eE=9,Pa=10,Na=11,tE=12,e0=14,Kf=3,nE=2,t0=1,iE=0,Wf=1,n0=2,rE=3,sE=1,oE=2,aE=1,lE=2;var cE=1002,s0={998:{fieldPresence:1,enumType:2,repeatedFieldEncoding:2,utf8Validation:3,messageEncoding:1,jsonFormat:2,enforceNamingStyle:2,defaultSymbolVisibility:1,enforceProtoLimits:1},999:{fieldPresence:2,enumType:1,repeatedFieldEncoding:1,utf8Validation:2,messageEncoding:1,jsonFormat:1,enforceNamingStyle:2,defaultSymbolVisibility:1,enforceProtoLimits:1},1e3:{fieldPresence:1,enumType:1,repeatedFieldEncoding:1,utf8Validation:2,messageEncoding:1,jsonFormat:1,enforceNamingStyle:2,defaultSymbolVisibility:1,enforceProtoLimits:1},1001:{fieldPresence:1,enumType:1,repeatedFieldEncoding:1,utf8Validation:2,messageEncoding:1,jsonFormat:1,enforceNamingStyle:1,defaultSymbolVisibility:2,enforceProtoLimits:1},1002:{fieldPresence:1,enumType:1,repeatedFieldEncoding:1,utf8Validation:2,messageEncoding:1,jsonFormat:1,enforceNamingStyle:3,defaultSymbolVisibility:4,enforceProtoLimits:2}};function i0(n,e){var t,i;let r={kind:"file",proto:n,deprecated:(i=(t=n.options)===null||t===void 0?void 0:t.deprecated)!==null&&i!==void 0?i:!1,edition:dE(n),name:n.name.replace(/\.proto$/,""),dependencies:pE(n,e),enums:[],messages:[],extensions:[],services:[],toString(){return`file ${n.name}`}},s=new Map,o={get(a){return s.get(a)},add(a){var l;zi(((l=a.proto.options)===null||l===void 0?void 0:l.mapEntry)===!0),s.set(a.typeName,a)}};for(let a of n.enumType)o0(a,r,void 0,e);for(let a of n.messageType)a0(a,r,void 0,e,o);for(let a of n.service)uE(a,r,e);Xf(r,e);for(let a of s.values())Yf(a,e,o);for(let a of r.messages)Yf(a,e,o),Xf(a,e);e.addFile(r,!0)}function Xf(n,e){switch(n.kind){case"file":for(let t of n.proto.extension){let i=Zf(t,n,e);n.extensions.push(i),e.add(i)}break;case"message":for(let t of n.proto.extension){let i=Zf(t,n,e);n.nestedExtensions.push(i),e.add(i)}for(let t of n.nestedMessages)Xf(t,e);break}}function Yf(n,e,t){let i=n.proto.oneofDecl.map(s=>fE(s,n)),r=new Set;for(let s of n.proto.field){let o=yE(s,i),a=Zf(s,n,e,o,t);n.fields.push(a),n.field[a.localName]=a,o===void 0?n.members.push(a):(o.fields.push(a),r.has(o)||(r.add(o),n.members.push(o)))}for(let s of i.filter(o=>r.has(o)))n.oneofs.push(s);for(let s of n.nestedMessages)Yf(s,e,t)}function o0(n,e,t,i){var r,s,o,a,l,c,u,h,f;let d=mE(n.name,n.value),p={kind:"enum",proto:n,deprecated:(s=(r=n.options)===null||r===void 0?void 0:r.deprecated)!==null&&s!==void 0?s:!1,file:e,parent:t,open:!0,name:n.name,typeName:rc(n,t,e),value:{},values:[],sharedPrefix:d,toString(){return`enum ${this.typeName}`}};p.open=SE(p),i.add(p);for(let x of n.value){let m=x.name,g={kind:"enum_value",proto:x,deprecated:(a=(o=x.options)===null||o===void 0?void 0:o.deprecated)!==null&&a!==void 0?a:!1,parent:p,name:m,localName:ao(d==null?m:m.substring(d.length)),number:x.number,jsonName:(l=gE(x))!==null&&l!==void 0?l:m,toString(){return`enum value ${p.typeName}.${m}`}};p.values.push(g),(c=(h=p.value)[f=x.number])!==null&&c!==void 0||(h[f]=g)}((u=t?.nestedEnums)!==null&&u!==void 0?u:e.enums).push(p)}function a0(n,e,t,i,r){var s,o,a,l;let c={kind:"message",proto:n,deprecated:(o=(s=n.options)===null||s===void 0?void 0:s.deprecated)!==null&&o!==void 0?o:!1,file:e,parent:t,name:n.name,typeName:rc(n,t,e),fields:[],field:{},oneofs:[],members:[],nestedEnums:[],nestedMessages:[],nestedExtensions:[],toString(){return`message ${this.typeName}`}};((a=n.options)===null||a===void 0?void 0:a.mapEntry)===!0?r.add(c):(((l=t?.nestedMessages)!==null&&l!==void 0?l:e.messages).push(c),i.add(c));for(let u of n.enumType)o0(u,e,c,i);for(let u of n.nestedType)a0(u,e,c,i,r)}function uE(n,e,t){var i,r;let s={kind:"service",proto:n,deprecated:(r=(i=n.options)===null||i===void 0?void 0:i.deprecated)!==null&&r!==void 0?r:!1,file:e,name:n.name,typeName:rc(n,void 0,e),methods:[],method:{},toString(){return`service ${this.typeName}`}};e.services.push(s),t.add(s);for(let o of n.method){let a=hE(o,s,t);s.methods.push(a),s.method[a.localName]=a}}function hE(n,e,t){var i,r,s,o;let a;n.clientStreaming&&n.serverStreaming?a="bidi_streaming":n.clientStreaming?a="client_streaming":n.serverStreaming?a="server_streaming":a="unary";let l=t.getMessage(Ir(n.inputType)),c=t.getMessage(Ir(n.outputType));zi(l,`invalid MethodDescriptorProto: input_type ${n.inputType} not found`),zi(c,`invalid MethodDescriptorProto: output_type ${n.inputType} not found`);let u=n.name;return{kind:"rpc",proto:n,deprecated:(r=(i=n.options)===null||i===void 0?void 0:i.deprecated)!==null&&r!==void 0?r:!1,parent:e,name:u,localName:ao(u.length?ao(u[0].toLowerCase()+u.substring(1)):u),methodKind:a,input:l,output:c,idempotency:(o=(s=n.options)===null||s===void 0?void 0:s.idempotencyLevel)!==null&&o!==void 0?o:iE,toString(){return`rpc ${e.typeName}.${u}`}}}function fE(n,e){return{kind:"oneof",proto:n,deprecated:!1,parent:e,fields:[],name:n.name,localName:ao(Rr(n.name)),toString(){return`oneof ${e.typeName}.${this.name}`}}}function Zf(n,e,t,i,r){var s,o,a;let l=r===void 0,c={kind:"field",proto:n,deprecated:(o=(s=n.options)===null||s===void 0?void 0:s.deprecated)!==null&&o!==void 0?o:!1,name:n.name,number:n.number,scalar:void 0,message:void 0,enum:void 0,presence:xE(n,i,l,e),utf8Validation:EE(n,e),listKind:void 0,mapKind:void 0,mapKey:void 0,delimitedEncoding:void 0,packed:void 0,longAsString:!1,getDefaultValue:void 0},u;if(l){let p=e.kind=="file"?e:e.file,x=e.kind=="file"?void 0:e,m=rc(n,x,p);c.kind="extension",c.file=p,c.parent=x,c.oneof=void 0,c.typeName=m,c.jsonName=`[${m}]`,u=()=>`extension ${m}`;let g=t.getMessage(Ir(n.extendee));zi(g,`invalid FieldDescriptorProto: extendee ${n.extendee} not found`),c.extendee=g}else{let p=e;zi(p.kind=="message"),c.parent=p,c.oneof=i,c.localName=i?Rr(n.name):ao(Rr(n.name)),c.jsonName=n.jsonName,u=()=>`field ${p.typeName}.${n.name}`}Object.defineProperty(c,"toString",{value:u,writable:!0,enumerable:!0,configurable:!0});let h=n.label,f=n.type,d=(a=n.options)===null||a===void 0?void 0:a.jstype;if(h===Kf){let p=f==Na?r?.get(Ir(n.typeName)):void 0;if(p){c.fieldKind="map";let{key:x,value:m}=vE(p);return c.mapKey=x.scalar,c.mapKind=m.fieldKind,c.message=m.message,c.delimitedEncoding=!1,c.enum=m.enum,c.scalar=m.scalar,c}switch(c.fieldKind="list",f){case Na:case Pa:c.listKind="message",c.message=t.getMessage(Ir(n.typeName)),zi(c.message),c.delimitedEncoding=r0(n,e);break;case e0:c.listKind="enum",c.enum=t.getEnum(Ir(n.typeName)),zi(c.enum);break;default:c.listKind="scalar",c.scalar=f,c.longAsString=d==t0;break}return c.packed=bE(n,e),c}switch(f){case Na:case Pa:c.fieldKind="message",c.message=t.getMessage(Ir(n.typeName)),zi(c.message,`invalid FieldDescriptorProto: type_name ${n.typeName} not found`),c.delimitedEncoding=r0(n,e),c.getDefaultValue=()=>{};break;case e0:{let p=t.getEnum(Ir(n.typeName));zi(p!==void 0,`invalid FieldDescriptorProto: type_name ${n.typeName} not found`),c.fieldKind="enum",c.enum=t.getEnum(Ir(n.typeName)),c.getDefaultValue=()=>ws(n,"defaultValue")?jg(p,n.defaultValue):void 0;break}default:{c.fieldKind="scalar",c.scalar=f,c.longAsString=d==t0,c.getDefaultValue=()=>ws(n,"defaultValue")?Qg(f,n.defaultValue):void 0;break}}return c}function dE(n){switch(n.syntax){case"":case"proto2":return JS;case"proto3":return jS;case"editions":if(n.edition===QS)return cE;if(n.edition in s0)return n.edition;throw new Error(`${n.name}: unsupported edition`);default:throw new Error(`${n.name}: unsupported syntax "${n.syntax}"`)}}function pE(n,e){return n.dependency.map(t=>{let i=e.getFile(t);if(!i)throw new Error(`Cannot find ${t}, imported by ${n.name}`);return i})}function mE(n,e){let t=_E(n)+"_";for(let i of e){if(!i.name.toLowerCase().startsWith(t))return;let r=i.name.substring(t.length);if(r.length==0||/^\d/.test(r))return}return t}function gE(n){var e,t;let s;for(let o of(t=(e=n.options)===null||e===void 0?void 0:e.$unknown)!==null&&t!==void 0?t:[]){if(o.no!==998||o.wireType!==Gt.LengthDelimited)continue;let a=new ur(new ur(o.data).bytes());for(;a.pos<a.len;){let[l,c]=a.tag();l===1&&c===Gt.LengthDelimited?s=a.string():a.skip(c,l)}}return s}function _E(n){return(n.substring(0,1)+n.substring(1).replace(/[A-Z]/g,e=>"_"+e)).toLowerCase()}function rc(n,e,t){let i;return e?i=`${e.typeName}.${n.name}`:t.proto.package.length>0?i=`${t.proto.package}.${n.name}`:i=`${n.name}`,i}function Ir(n){return n.startsWith(".")?n.substring(1):n}function yE(n,e){if(!ws(n,"oneofIndex")||n.proto3Optional)return;let t=e[n.oneofIndex];return zi(t,`invalid FieldDescriptorProto: oneof #${n.oneofIndex} for field #${n.number} not found`),t}function xE(n,e,t,i){if(n.label==nE)return rE;if(n.label==Kf)return n0;if(e||n.proto3Optional||t)return Wf;let r=Ts("fieldPresence",{proto:n,parent:i});return r==n0&&(n.type==Na||n.type==Pa)?Wf:r}function bE(n,e){if(n.label!=Kf)return!1;switch(n.type){case eE:case tE:case Pa:case Na:return!1}let t=n.options;return t&&ws(t,"packed")?t.packed:sE==Ts("repeatedFieldEncoding",{proto:n,parent:e})}function vE(n){let e=n.fields.find(i=>i.number===1),t=n.fields.find(i=>i.number===2);return zi(e&&e.fieldKind=="scalar"&&e.scalar!=V.BYTES&&e.scalar!=V.FLOAT&&e.scalar!=V.DOUBLE&&t&&t.fieldKind!="list"&&t.fieldKind!="map"),{key:e,value:t}}function SE(n){var e;return aE==Ts("enumType",{proto:n.proto,parent:(e=n.parent)!==null&&e!==void 0?e:n.file})}function r0(n,e){return n.type==Pa?!0:oE==Ts("messageEncoding",{proto:n,parent:e})}function EE(n,e){return lE==Ts("utf8Validation",{proto:n,parent:e})}function Ts(n,e){var t,i;let r=(t=e.proto.options)===null||t===void 0?void 0:t.features;if(r){let s=r[n];if(s!=0)return s}if("kind"in e){if(e.kind=="message")return Ts(n,(i=e.parent)!==null&&i!==void 0?i:e.file);let s=s0[e.edition];if(!s)throw new Error(`feature default for edition ${e.edition} not found`);return s[n]}return Ts(n,e.parent)}function zi(n,e){if(!n)throw new Error(e)}function l0(n){let e=ME(n);return e.messageType.forEach(Ca),ic(e,()=>{}).getFile(e.name)}function ME(n){return Object.assign(Object.create({syntax:"",edition:0}),Object.assign(Object.assign({$typeName:"google.protobuf.FileDescriptorProto",dependency:[],publicDependency:[],weakDependency:[],optionDependency:[],service:[],extension:[]},n),{messageType:n.messageType.map(c0),enumType:n.enumType.map(u0)}))}function c0(n){var e,t,i,r,s,o,a,l;return Object.assign(Object.create({visibility:0}),{$typeName:"google.protobuf.DescriptorProto",name:n.name,field:(t=(e=n.field)===null||e===void 0?void 0:e.map(wE))!==null&&t!==void 0?t:[],extension:[],nestedType:(r=(i=n.nestedType)===null||i===void 0?void 0:i.map(c0))!==null&&r!==void 0?r:[],enumType:(o=(s=n.enumType)===null||s===void 0?void 0:s.map(u0))!==null&&o!==void 0?o:[],extensionRange:(l=(a=n.extensionRange)===null||a===void 0?void 0:a.map(u=>Object.assign({$typeName:"google.protobuf.DescriptorProto.ExtensionRange"},u)))!==null&&l!==void 0?l:[],oneofDecl:[],reservedRange:[],reservedName:[]})}function wE(n){return Object.assign(Object.create({label:1,typeName:"",extendee:"",defaultValue:"",oneofIndex:0,jsonName:"",proto3Optional:!1}),Object.assign(Object.assign({$typeName:"google.protobuf.FieldDescriptorProto"},n),{options:n.options?TE(n.options):void 0}))}function TE(n){var e,t,i;return Object.assign(Object.create({ctype:0,packed:!1,jstype:0,lazy:!1,unverifiedLazy:!1,deprecated:!1,weak:!1,debugRedact:!1,retention:0}),Object.assign(Object.assign({$typeName:"google.protobuf.FieldOptions"},n),{targets:(e=n.targets)!==null&&e!==void 0?e:[],editionDefaults:(i=(t=n.editionDefaults)===null||t===void 0?void 0:t.map(s=>Object.assign({$typeName:"google.protobuf.FieldOptions.EditionDefault"},s)))!==null&&i!==void 0?i:[],uninterpretedOption:[]}))}function u0(n){return Object.assign(Object.create({visibility:0}),{$typeName:"google.protobuf.EnumDescriptorProto",name:n.name,reservedName:[],reservedRange:[],value:n.value.map(t=>Object.assign({$typeName:"google.protobuf.EnumValueDescriptorProto"},t))})}function vn(n,e,...t){return t.reduce((i,r)=>i.nestedMessages[r],n.messages[e])}var AE=l0({name:"google/protobuf/descriptor.proto",package:"google.protobuf",messageType:[{name:"FileDescriptorSet",field:[{name:"file",number:1,type:11,label:3,typeName:".google.protobuf.FileDescriptorProto"}],extensionRange:[{start:536e6,end:536000001}]},{name:"FileDescriptorProto",field:[{name:"name",number:1,type:9,label:1},{name:"package",number:2,type:9,label:1},{name:"dependency",number:3,type:9,label:3},{name:"public_dependency",number:10,type:5,label:3},{name:"weak_dependency",number:11,type:5,label:3},{name:"option_dependency",number:15,type:9,label:3},{name:"message_type",number:4,type:11,label:3,typeName:".google.protobuf.DescriptorProto"},{name:"enum_type",number:5,type:11,label:3,typeName:".google.protobuf.EnumDescriptorProto"},{name:"service",number:6,type:11,label:3,typeName:".google.protobuf.ServiceDescriptorProto"},{name:"extension",number:7,type:11,label:3,typeName:".google.protobuf.FieldDescriptorProto"},{name:"options",number:8,type:11,label:1,typeName:".google.protobuf.FileOptions"},{name:"source_code_info",number:9,type:11,label:1,typeName:".google.protobuf.SourceCodeInfo"},{name:"syntax",number:12,type:9,label:1},{name:"edition",number:14,type:14,label:1,typeName:".google.protobuf.Edition"}]},{name:"DescriptorProto",field:[{name:"name",number:1,type:9,label:1},{name:"field",number:2,type:11,label:3,typeName:".google.protobuf.FieldDescriptorProto"},{name:"extension",number:6,type:11,label:3,typeName:".google.protobuf.FieldDescriptorProto"},{name:"nested_type",number:3,type:11,label:3,typeName:".google.protobuf.DescriptorProto"},{name:"enum_type",number:4,type:11,label:3,typeName:".google.protobuf.EnumDescriptorProto"},{name:"extension_range",number:5,type:11,label:3,typeName:".google.protobuf.DescriptorProto.ExtensionRange"},{name:"oneof_decl",number:8,type:11,label:3,typeName:".google.protobuf.OneofDescriptorProto"},{name:"options",number:7,type:11,label:1,typeName:".google.protobuf.MessageOptions"},{name:"reserved_range",number:9,type:11,label:3,typeName:".google.protobuf.DescriptorProto.ReservedRange"},{name:"reserved_name",number:10,type:9,label:3},{name:"visibility",number:11,type:14,label:1,typeName:".google.protobuf.SymbolVisibility"}],nestedType:[{name:"ExtensionRange",field:[{name:"start",number:1,type:5,label:1},{name:"end",number:2,type:5,label:1},{name:"options",number:3,type:11,label:1,typeName:".google.protobuf.ExtensionRangeOptions"}]},{name:"ReservedRange",field:[{name:"start",number:1,type:5,label:1},{name:"end",number:2,type:5,label:1}]}]},{name:"ExtensionRangeOptions",field:[{name:"uninterpreted_option",number:999,type:11,label:3,typeName:".google.protobuf.UninterpretedOption"},{name:"declaration",number:2,type:11,label:3,typeName:".google.protobuf.ExtensionRangeOptions.Declaration",options:{retention:2}},{name:"features",number:50,type:11,label:1,typeName:".google.protobuf.FeatureSet"},{name:"verification",number:3,type:14,label:1,typeName:".google.protobuf.ExtensionRangeOptions.VerificationState",defaultValue:"UNVERIFIED",options:{retention:2}}],nestedType:[{name:"Declaration",field:[{name:"number",number:1,type:5,label:1},{name:"full_name",number:2,type:9,label:1},{name:"type",number:3,type:9,label:1},{name:"reserved",number:5,type:8,label:1},{name:"repeated",number:6,type:8,label:1}]}],enumType:[{name:"VerificationState",value:[{name:"DECLARATION",number:0},{name:"UNVERIFIED",number:1}]}],extensionRange:[{start:990,end:999},{start:1e3,end:536870912}]},{name:"FieldDescriptorProto",field:[{name:"name",number:1,type:9,label:1},{name:"number",number:3,type:5,label:1},{name:"label",number:4,type:14,label:1,typeName:".google.protobuf.FieldDescriptorProto.Label"},{name:"type",number:5,type:14,label:1,typeName:".google.protobuf.FieldDescriptorProto.Type"},{name:"type_name",number:6,type:9,label:1},{name:"extendee",number:2,type:9,label:1},{name:"default_value",number:7,type:9,label:1},{name:"oneof_index",number:9,type:5,label:1},{name:"json_name",number:10,type:9,label:1},{name:"options",number:8,type:11,label:1,typeName:".google.protobuf.FieldOptions"},{name:"proto3_optional",number:17,type:8,label:1}],enumType:[{name:"Type",value:[{name:"TYPE_DOUBLE",number:1},{name:"TYPE_FLOAT",number:2},{name:"TYPE_INT64",number:3},{name:"TYPE_UINT64",number:4},{name:"TYPE_INT32",number:5},{name:"TYPE_FIXED64",number:6},{name:"TYPE_FIXED32",number:7},{name:"TYPE_BOOL",number:8},{name:"TYPE_STRING",number:9},{name:"TYPE_GROUP",number:10},{name:"TYPE_MESSAGE",number:11},{name:"TYPE_BYTES",number:12},{name:"TYPE_UINT32",number:13},{name:"TYPE_ENUM",number:14},{name:"TYPE_SFIXED32",number:15},{name:"TYPE_SFIXED64",number:16},{name:"TYPE_SINT32",number:17},{name:"TYPE_SINT64",number:18}]},{name:"Label",value:[{name:"LABEL_OPTIONAL",number:1},{name:"LABEL_REPEATED",number:3},{name:"LABEL_REQUIRED",number:2}]}]},{name:"OneofDescriptorProto",field:[{name:"name",number:1,type:9,label:1},{name:"options",number:2,type:11,label:1,typeName:".google.protobuf.OneofOptions"}]},{name:"EnumDescriptorProto",field:[{name:"name",number:1,type:9,label:1},{name:"value",number:2,type:11,label:3,typeName:".google.protobuf.EnumValueDescriptorProto"},{name:"options",number:3,type:11,label:1,typeName:".google.protobuf.EnumOptions"},{name:"reserved_range",number:4,type:11,label:3,typeName:".google.protobuf.EnumDescriptorProto.EnumReservedRange"},{name:"reserved_name",number:5,type:9,label:3},{name:"visibility",number:6,type:14,label:1,typeName:".google.protobuf.SymbolVisibility"}],nestedType:[{name:"EnumReservedRange",field:[{name:"start",number:1,type:5,label:1},{name:"end",number:2,type:5,label:1}]}]},{name:"EnumValueDescriptorProto",field:[{name:"name",number:1,type:9,label:1},{name:"number",number:2,type:5,label:1},{name:"options",number:3,type:11,label:1,typeName:".google.protobuf.EnumValueOptions"}]},{name:"ServiceDescriptorProto",field:[{name:"name",number:1,type:9,label:1},{name:"method",number:2,type:11,label:3,typeName:".google.protobuf.MethodDescriptorProto"},{name:"options",number:3,type:11,label:1,typeName:".google.protobuf.ServiceOptions"}]},{name:"MethodDescriptorProto",field:[{name:"name",number:1,type:9,label:1},{name:"input_type",number:2,type:9,label:1},{name:"output_type",number:3,type:9,label:1},{name:"options",number:4,type:11,label:1,typeName:".google.protobuf.MethodOptions"},{name:"client_streaming",number:5,type:8,label:1,defaultValue:"false"},{name:"server_streaming",number:6,type:8,label:1,defaultValue:"false"}]},{name:"FileOptions",field:[{name:"java_package",number:1,type:9,label:1},{name:"java_outer_classname",number:8,type:9,label:1},{name:"java_multiple_files",number:10,type:8,label:1,defaultValue:"false",options:{}},{name:"java_generate_equals_and_hash",number:20,type:8,label:1,options:{deprecated:!0}},{name:"java_string_check_utf8",number:27,type:8,label:1,defaultValue:"false"},{name:"optimize_for",number:9,type:14,label:1,typeName:".google.protobuf.FileOptions.OptimizeMode",defaultValue:"SPEED"},{name:"go_package",number:11,type:9,label:1},{name:"cc_generic_services",number:16,type:8,label:1,defaultValue:"false"},{name:"java_generic_services",number:17,type:8,label:1,defaultValue:"false"},{name:"py_generic_services",number:18,type:8,label:1,defaultValue:"false"},{name:"deprecated",number:23,type:8,label:1,defaultValue:"false"},{name:"cc_enable_arenas",number:31,type:8,label:1,defaultValue:"true",options:{}},{name:"objc_class_prefix",number:36,type:9,label:1},{name:"csharp_namespace",number:37,type:9,label:1},{name:"swift_prefix",number:39,type:9,label:1},{name:"php_class_prefix",number:40,type:9,label:1},{name:"php_namespace",number:41,type:9,label:1},{name:"php_metadata_namespace",number:44,type:9,label:1},{name:"ruby_package",number:45,type:9,label:1},{name:"features",number:50,type:11,label:1,typeName:".google.protobuf.FeatureSet"},{name:"uninterpreted_option",number:999,type:11,label:3,typeName:".google.protobuf.UninterpretedOption"}],enumType:[{name:"OptimizeMode",value:[{name:"SPEED",number:1},{name:"CODE_SIZE",number:2},{name:"LITE_RUNTIME",number:3}]}],extensionRange:[{start:990,end:999},{start:1e3,end:536870912}]},{name:"MessageOptions",field:[{name:"message_set_wire_format",number:1,type:8,label:1,defaultValue:"false"},{name:"no_standard_descriptor_accessor",number:2,type:8,label:1,defaultValue:"false"},{name:"deprecated",number:3,type:8,label:1,defaultValue:"false"},{name:"map_entry",number:7,type:8,label:1},{name:"deprecated_legacy_json_field_conflicts",number:11,type:8,label:1,options:{deprecated:!0}},{name:"features",number:12,type:11,label:1,typeName:".google.protobuf.FeatureSet"},{name:"uninterpreted_option",number:999,type:11,label:3,typeName:".google.protobuf.UninterpretedOption"}],extensionRange:[{start:990,end:999},{start:1e3,end:536870912}]},{name:"FieldOptions",field:[{name:"ctype",number:1,type:14,label:1,typeName:".google.protobuf.FieldOptions.CType",defaultValue:"STRING"},{name:"packed",number:2,type:8,label:1},{name:"jstype",number:6,type:14,label:1,typeName:".google.protobuf.FieldOptions.JSType",defaultValue:"JS_NORMAL"},{name:"lazy",number:5,type:8,label:1,defaultValue:"false"},{name:"unverified_lazy",number:15,type:8,label:1,defaultValue:"false"},{name:"deprecated",number:3,type:8,label:1,defaultValue:"false"},{name:"weak",number:10,type:8,label:1,defaultValue:"false",options:{deprecated:!0}},{name:"debug_redact",number:16,type:8,label:1,defaultValue:"false"},{name:"retention",number:17,type:14,label:1,typeName:".google.protobuf.FieldOptions.OptionRetention"},{name:"targets",number:19,type:14,label:3,typeName:".google.protobuf.FieldOptions.OptionTargetType"},{name:"edition_defaults",number:20,type:11,label:3,typeName:".google.protobuf.FieldOptions.EditionDefault"},{name:"features",number:21,type:11,label:1,typeName:".google.protobuf.FeatureSet"},{name:"feature_support",number:22,type:11,label:1,typeName:".google.protobuf.FieldOptions.FeatureSupport"},{name:"uninterpreted_option",number:999,type:11,label:3,typeName:".google.protobuf.UninterpretedOption"}],nestedType:[{name:"EditionDefault",field:[{name:"edition",number:3,type:14,label:1,typeName:".google.protobuf.Edition"},{name:"value",number:2,type:9,label:1}]},{name:"FeatureSupport",field:[{name:"edition_introduced",number:1,type:14,label:1,typeName:".google.protobuf.Edition"},{name:"edition_deprecated",number:2,type:14,label:1,typeName:".google.protobuf.Edition"},{name:"deprecation_warning",number:3,type:9,label:1},{name:"edition_removed",number:4,type:14,label:1,typeName:".google.protobuf.Edition"},{name:"removal_error",number:5,type:9,label:1}]}],enumType:[{name:"CType",value:[{name:"STRING",number:0},{name:"CORD",number:1},{name:"STRING_PIECE",number:2}]},{name:"JSType",value:[{name:"JS_NORMAL",number:0},{name:"JS_STRING",number:1},{name:"JS_NUMBER",number:2}]},{name:"OptionRetention",value:[{name:"RETENTION_UNKNOWN",number:0},{name:"RETENTION_RUNTIME",number:1},{name:"RETENTION_SOURCE",number:2}]},{name:"OptionTargetType",value:[{name:"TARGET_TYPE_UNKNOWN",number:0},{name:"TARGET_TYPE_FILE",number:1},{name:"TARGET_TYPE_EXTENSION_RANGE",number:2},{name:"TARGET_TYPE_MESSAGE",number:3},{name:"TARGET_TYPE_FIELD",number:4},{name:"TARGET_TYPE_ONEOF",number:5},{name:"TARGET_TYPE_ENUM",number:6},{name:"TARGET_TYPE_ENUM_ENTRY",number:7},{name:"TARGET_TYPE_SERVICE",number:8},{name:"TARGET_TYPE_METHOD",number:9}]}],extensionRange:[{start:990,end:999},{start:1e3,end:536870912}]},{name:"OneofOptions",field:[{name:"features",number:1,type:11,label:1,typeName:".google.protobuf.FeatureSet"},{name:"uninterpreted_option",number:999,type:11,label:3,typeName:".google.protobuf.UninterpretedOption"}],extensionRange:[{start:990,end:999},{start:1e3,end:536870912}]},{name:"EnumOptions",field:[{name:"allow_alias",number:2,type:8,label:1},{name:"deprecated",number:3,type:8,label:1,defaultValue:"false"},{name:"deprecated_legacy_json_field_conflicts",number:6,type:8,label:1,options:{deprecated:!0}},{name:"features",number:7,type:11,label:1,typeName:".google.protobuf.FeatureSet"},{name:"uninterpreted_option",number:999,type:11,label:3,typeName:".google.protobuf.UninterpretedOption"}],extensionRange:[{start:990,end:999},{start:1e3,end:536870912}]},{name:"EnumValueOptions",field:[{name:"deprecated",number:1,type:8,label:1,defaultValue:"false"},{name:"features",number:2,type:11,label:1,typeName:".google.protobuf.FeatureSet"},{name:"debug_redact",number:3,type:8,label:1,defaultValue:"false"},{name:"feature_support",number:4,type:11,label:1,typeName:".google.protobuf.FieldOptions.FeatureSupport"},{name:"uninterpreted_option",number:999,type:11,label:3,typeName:".google.protobuf.UninterpretedOption"}],extensionRange:[{start:990,end:999},{start:1e3,end:536870912}]},{name:"ServiceOptions",field:[{name:"features",number:34,type:11,label:1,typeName:".google.protobuf.FeatureSet"},{name:"deprecated",number:33,type:8,label:1,defaultValue:"false"},{name:"uninterpreted_option",number:999,type:11,label:3,typeName:".google.protobuf.UninterpretedOption"}],extensionRange:[{start:990,end:999},{start:1e3,end:536870912}]},{name:"MethodOptions",field:[{name:"deprecated",number:33,type:8,label:1,defaultValue:"false"},{name:"idempotency_level",number:34,type:14,label:1,typeName:".google.protobuf.MethodOptions.IdempotencyLevel",defaultValue:"IDEMPOTENCY_UNKNOWN"},{name:"features",number:35,type:11,label:1,typeName:".google.protobuf.FeatureSet"},{name:"uninterpreted_option",number:999,type:11,label:3,typeName:".google.protobuf.UninterpretedOption"}],enumType:[{name:"IdempotencyLevel",value:[{name:"IDEMPOTENCY_UNKNOWN",number:0},{name:"NO_SIDE_EFFECTS",number:1},{name:"IDEMPOTENT",number:2}]}],extensionRange:[{start:990,end:999},{start:1e3,end:536870912}]},{name:"UninterpretedOption",field:[{name:"name",number:2,type:11,label:3,typeName:".google.protobuf.UninterpretedOption.NamePart"},{name:"identifier_value",number:3,type:9,label:1},{name:"positive_int_value",number:4,type:4,label:1},{name:"negative_int_value",number:5,type:3,label:1},{name:"double_value",number:6,type:1,label:1},{name:"string_value",number:7,type:12,label:1},{name:"aggregate_value",number:8,type:9,label:1}],nestedType:[{name:"NamePart",field:[{name:"name_part",number:1,type:9,label:2},{name:"is_extension",number:2,type:8,label:2}]}]},{name:"FeatureSet",field:[{name:"field_presence",number:1,type:14,label:1,typeName:".google.protobuf.FeatureSet.FieldPresence",options:{retention:1,targets:[4,1],editionDefaults:[{value:"EXPLICIT",edition:900},{value:"IMPLICIT",edition:999},{value:"EXPLICIT",edition:1e3}]}},{name:"enum_type",number:2,type:14,label:1,typeName:".google.protobuf.FeatureSet.EnumType",options:{retention:1,targets:[6,1],editionDefaults:[{value:"CLOSED",edition:900},{value:"OPEN",edition:999}]}},{name:"repeated_field_encoding",number:3,type:14,label:1,typeName:".google.protobuf.FeatureSet.RepeatedFieldEncoding",options:{retention:1,targets:[4,1],editionDefaults:[{value:"EXPANDED",edition:900},{value:"PACKED",edition:999}]}},{name:"utf8_validation",number:4,type:14,label:1,typeName:".google.protobuf.FeatureSet.Utf8Validation",options:{retention:1,targets:[4,1],editionDefaults:[{value:"NONE",edition:900},{value:"VERIFY",edition:999}]}},{name:"message_encoding",number:5,type:14,label:1,typeName:".google.protobuf.FeatureSet.MessageEncoding",options:{retention:1,targets:[4,1],editionDefaults:[{value:"LENGTH_PREFIXED",edition:900}]}},{name:"json_format",number:6,type:14,label:1,typeName:".google.protobuf.FeatureSet.JsonFormat",options:{retention:1,targets:[3,6,1],editionDefaults:[{value:"LEGACY_BEST_EFFORT",edition:900},{value:"ALLOW",edition:999}]}},{name:"enforce_naming_style",number:7,type:14,label:1,typeName:".google.protobuf.FeatureSet.EnforceNamingStyle",options:{retention:2,targets:[1,2,3,4,5,6,7,8,9],editionDefaults:[{value:"STYLE_LEGACY",edition:900},{value:"STYLE2024",edition:1001},{value:"STYLE2026",edition:1002}]}},{name:"default_symbol_visibility",number:8,type:14,label:1,typeName:".google.protobuf.FeatureSet.VisibilityFeature.DefaultSymbolVisibility",options:{retention:2,targets:[1],editionDefaults:[{value:"EXPORT_ALL",edition:900},{value:"EXPORT_TOP_LEVEL",edition:1001},{value:"STRICT",edition:1002}]}},{name:"enforce_proto_limits",number:9,type:14,label:1,typeName:".google.protobuf.FeatureSet.ProtoLimitsFeature.EnforceProtoLimits",options:{retention:2,targets:[6,3,4,5],editionDefaults:[{value:"LEGACY_NO_EXPLICIT_LIMITS",edition:900},{value:"PROTO_LIMITS2026",edition:1002}]}}],nestedType:[{name:"VisibilityFeature",enumType:[{name:"DefaultSymbolVisibility",value:[{name:"DEFAULT_SYMBOL_VISIBILITY_UNKNOWN",number:0},{name:"EXPORT_ALL",number:1},{name:"EXPORT_TOP_LEVEL",number:2},{name:"LOCAL_ALL",number:3},{name:"STRICT",number:4}]}]},{name:"ProtoLimitsFeature",enumType:[{name:"EnforceProtoLimits",value:[{name:"PROTO_LIMITS_UNKNOWN",number:0},{name:"LEGACY_NO_EXPLICIT_LIMITS",number:1},{name:"PROTO_LIMITS2026",number:2}]}]}],enumType:[{name:"FieldPresence",value:[{name:"FIELD_PRESENCE_UNKNOWN",number:0},{name:"EXPLICIT",number:1},{name:"IMPLICIT",number:2},{name:"LEGACY_REQUIRED",number:3}]},{name:"EnumType",value:[{name:"ENUM_TYPE_UNKNOWN",number:0},{name:"OPEN",number:1},{name:"CLOSED",number:2}]},{name:"RepeatedFieldEncoding",value:[{name:"REPEATED_FIELD_ENCODING_UNKNOWN",number:0},{name:"PACKED",number:1},{name:"EXPANDED",number:2}]},{name:"Utf8Validation",value:[{name:"UTF8_VALIDATION_UNKNOWN",number:0},{name:"VERIFY",number:2},{name:"NONE",number:3}]},{name:"MessageEncoding",value:[{name:"MESSAGE_ENCODING_UNKNOWN",number:0},{name:"LENGTH_PREFIXED",number:1},{name:"DELIMITED",number:2}]},{name:"JsonFormat",value:[{name:"JSON_FORMAT_UNKNOWN",number:0},{name:"ALLOW",number:1},{name:"LEGACY_BEST_EFFORT",number:2}]},{name:"EnforceNamingStyle",value:[{name:"ENFORCE_NAMING_STYLE_UNKNOWN",number:0},{name:"STYLE2024",number:1},{name:"STYLE_LEGACY",number:2},{name:"STYLE2026",number:3}]}],extensionRange:[{start:1e3,end:9995},{start:9995,end:1e4},{start:1e4,end:10001}]},{name:"FeatureSetDefaults",field:[{name:"defaults",number:1,type:11,label:3,typeName:".google.protobuf.FeatureSetDefaults.FeatureSetEditionDefault"},{name:"minimum_edition",number:4,type:14,label:1,typeName:".google.protobuf.Edition"},{name:"maximum_edition",number:5,type:14,label:1,typeName:".google.protobuf.Edition"}],nestedType:[{name:"FeatureSetEditionDefault",field:[{name:"edition",number:3,type:14,label:1,typeName:".google.protobuf.Edition"},{name:"overridable_features",number:4,type:11,label:1,typeName:".google.protobuf.FeatureSet"},{name:"fixed_features",number:5,type:11,label:1,typeName:".google.protobuf.FeatureSet"}]}]},{name:"SourceCodeInfo",field:[{name:"location",number:1,type:11,label:3,typeName:".google.protobuf.SourceCodeInfo.Location"}],nestedType:[{name:"Location",field:[{name:"path",number:1,type:5,label:3,options:{packed:!0}},{name:"span",number:2,type:5,label:3,options:{packed:!0}},{name:"leading_comments",number:3,type:9,label:1},{name:"trailing_comments",number:4,type:9,label:1},{name:"leading_detached_comments",number:6,type:9,label:3}]}],extensionRange:[{start:536e6,end:536000001}]},{name:"GeneratedCodeInfo",field:[{name:"annotation",number:1,type:11,label:3,typeName:".google.protobuf.GeneratedCodeInfo.Annotation"}],nestedType:[{name:"Annotation",field:[{name:"path",number:1,type:5,label:3,options:{packed:!0}},{name:"source_file",number:2,type:9,label:1},{name:"begin",number:3,type:5,label:1},{name:"end",number:4,type:5,label:1},{name:"semantic",number:5,type:14,label:1,typeName:".google.protobuf.GeneratedCodeInfo.Annotation.Semantic"}],enumType:[{name:"Semantic",value:[{name:"NONE",number:0},{name:"SET",number:1},{name:"ALIAS",number:2}]}]}]}],enumType:[{name:"Edition",value:[{name:"EDITION_UNKNOWN",number:0},{name:"EDITION_LEGACY",number:900},{name:"EDITION_PROTO2",number:998},{name:"EDITION_PROTO3",number:999},{name:"EDITION_2023",number:1e3},{name:"EDITION_2024",number:1001},{name:"EDITION_2026",number:1002},{name:"EDITION_UNSTABLE",number:9999},{name:"EDITION_1_TEST_ONLY",number:1},{name:"EDITION_2_TEST_ONLY",number:2},{name:"EDITION_99997_TEST_ONLY",number:99997},{name:"EDITION_99998_TEST_ONLY",number:99998},{name:"EDITION_99999_TEST_ONLY",number:99999},{name:"EDITION_MAX",number:2147483647}]},{name:"SymbolVisibility",value:[{name:"VISIBILITY_UNSET",number:0},{name:"VISIBILITY_LOCAL",number:1},{name:"VISIBILITY_EXPORT",number:2}]}]});var P0=vn(AE,1);var h0;(function(n){n[n.DECLARATION=0]="DECLARATION",n[n.UNVERIFIED=1]="UNVERIFIED"})(h0||(h0={}));var f0;(function(n){n[n.DOUBLE=1]="DOUBLE",n[n.FLOAT=2]="FLOAT",n[n.INT64=3]="INT64",n[n.UINT64=4]="UINT64",n[n.INT32=5]="INT32",n[n.FIXED64=6]="FIXED64",n[n.FIXED32=7]="FIXED32",n[n.BOOL=8]="BOOL",n[n.STRING=9]="STRING",n[n.GROUP=10]="GROUP",n[n.MESSAGE=11]="MESSAGE",n[n.BYTES=12]="BYTES",n[n.UINT32=13]="UINT32",n[n.ENUM=14]="ENUM",n[n.SFIXED32=15]="SFIXED32",n[n.SFIXED64=16]="SFIXED64",n[n.SINT32=17]="SINT32",n[n.SINT64=18]="SINT64"})(f0||(f0={}));var d0;(function(n){n[n.OPTIONAL=1]="OPTIONAL",n[n.REPEATED=3]="REPEATED",n[n.REQUIRED=2]="REQUIRED"})(d0||(d0={}));var p0;(function(n){n[n.SPEED=1]="SPEED",n[n.CODE_SIZE=2]="CODE_SIZE",n[n.LITE_RUNTIME=3]="LITE_RUNTIME"})(p0||(p0={}));var m0;(function(n){n[n.STRING=0]="STRING",n[n.CORD=1]="CORD",n[n.STRING_PIECE=2]="STRING_PIECE"})(m0||(m0={}));var g0;(function(n){n[n.JS_NORMAL=0]="JS_NORMAL",n[n.JS_STRING=1]="JS_STRING",n[n.JS_NUMBER=2]="JS_NUMBER"})(g0||(g0={}));var _0;(function(n){n[n.RETENTION_UNKNOWN=0]="RETENTION_UNKNOWN",n[n.RETENTION_RUNTIME=1]="RETENTION_RUNTIME",n[n.RETENTION_SOURCE=2]="RETENTION_SOURCE"})(_0||(_0={}));var y0;(function(n){n[n.TARGET_TYPE_UNKNOWN=0]="TARGET_TYPE_UNKNOWN",n[n.TARGET_TYPE_FILE=1]="TARGET_TYPE_FILE",n[n.TARGET_TYPE_EXTENSION_RANGE=2]="TARGET_TYPE_EXTENSION_RANGE",n[n.TARGET_TYPE_MESSAGE=3]="TARGET_TYPE_MESSAGE",n[n.TARGET_TYPE_FIELD=4]="TARGET_TYPE_FIELD",n[n.TARGET_TYPE_ONEOF=5]="TARGET_TYPE_ONEOF",n[n.TARGET_TYPE_ENUM=6]="TARGET_TYPE_ENUM",n[n.TARGET_TYPE_ENUM_ENTRY=7]="TARGET_TYPE_ENUM_ENTRY",n[n.TARGET_TYPE_SERVICE=8]="TARGET_TYPE_SERVICE",n[n.TARGET_TYPE_METHOD=9]="TARGET_TYPE_METHOD"})(y0||(y0={}));var x0;(function(n){n[n.IDEMPOTENCY_UNKNOWN=0]="IDEMPOTENCY_UNKNOWN",n[n.NO_SIDE_EFFECTS=1]="NO_SIDE_EFFECTS",n[n.IDEMPOTENT=2]="IDEMPOTENT"})(x0||(x0={}));var b0;(function(n){n[n.DEFAULT_SYMBOL_VISIBILITY_UNKNOWN=0]="DEFAULT_SYMBOL_VISIBILITY_UNKNOWN",n[n.EXPORT_ALL=1]="EXPORT_ALL",n[n.EXPORT_TOP_LEVEL=2]="EXPORT_TOP_LEVEL",n[n.LOCAL_ALL=3]="LOCAL_ALL",n[n.STRICT=4]="STRICT"})(b0||(b0={}));var v0;(function(n){n[n.PROTO_LIMITS_UNKNOWN=0]="PROTO_LIMITS_UNKNOWN",n[n.LEGACY_NO_EXPLICIT_LIMITS=1]="LEGACY_NO_EXPLICIT_LIMITS",n[n.PROTO_LIMITS2026=2]="PROTO_LIMITS2026"})(v0||(v0={}));var S0;(function(n){n[n.FIELD_PRESENCE_UNKNOWN=0]="FIELD_PRESENCE_UNKNOWN",n[n.EXPLICIT=1]="EXPLICIT",n[n.IMPLICIT=2]="IMPLICIT",n[n.LEGACY_REQUIRED=3]="LEGACY_REQUIRED"})(S0||(S0={}));var E0;(function(n){n[n.ENUM_TYPE_UNKNOWN=0]="ENUM_TYPE_UNKNOWN",n[n.OPEN=1]="OPEN",n[n.CLOSED=2]="CLOSED"})(E0||(E0={}));var M0;(function(n){n[n.REPEATED_FIELD_ENCODING_UNKNOWN=0]="REPEATED_FIELD_ENCODING_UNKNOWN",n[n.PACKED=1]="PACKED",n[n.EXPANDED=2]="EXPANDED"})(M0||(M0={}));var w0;(function(n){n[n.UTF8_VALIDATION_UNKNOWN=0]="UTF8_VALIDATION_UNKNOWN",n[n.VERIFY=2]="VERIFY",n[n.NONE=3]="NONE"})(w0||(w0={}));var T0;(function(n){n[n.MESSAGE_ENCODING_UNKNOWN=0]="MESSAGE_ENCODING_UNKNOWN",n[n.LENGTH_PREFIXED=1]="LENGTH_PREFIXED",n[n.DELIMITED=2]="DELIMITED"})(T0||(T0={}));var A0;(function(n){n[n.JSON_FORMAT_UNKNOWN=0]="JSON_FORMAT_UNKNOWN",n[n.ALLOW=1]="ALLOW",n[n.LEGACY_BEST_EFFORT=2]="LEGACY_BEST_EFFORT"})(A0||(A0={}));var R0;(function(n){n[n.ENFORCE_NAMING_STYLE_UNKNOWN=0]="ENFORCE_NAMING_STYLE_UNKNOWN",n[n.STYLE2024=1]="STYLE2024",n[n.STYLE_LEGACY=2]="STYLE_LEGACY",n[n.STYLE2026=3]="STYLE2026"})(R0||(R0={}));var I0;(function(n){n[n.NONE=0]="NONE",n[n.SET=1]="SET",n[n.ALIAS=2]="ALIAS"})(I0||(I0={}));var C0;(function(n){n[n.EDITION_UNKNOWN=0]="EDITION_UNKNOWN",n[n.EDITION_LEGACY=900]="EDITION_LEGACY",n[n.EDITION_PROTO2=998]="EDITION_PROTO2",n[n.EDITION_PROTO3=999]="EDITION_PROTO3",n[n.EDITION_2023=1e3]="EDITION_2023",n[n.EDITION_2024=1001]="EDITION_2024",n[n.EDITION_2026=1002]="EDITION_2026",n[n.EDITION_UNSTABLE=9999]="EDITION_UNSTABLE",n[n.EDITION_1_TEST_ONLY=1]="EDITION_1_TEST_ONLY",n[n.EDITION_2_TEST_ONLY=2]="EDITION_2_TEST_ONLY",n[n.EDITION_99997_TEST_ONLY=99997]="EDITION_99997_TEST_ONLY",n[n.EDITION_99998_TEST_ONLY=99998]="EDITION_99998_TEST_ONLY",n[n.EDITION_99999_TEST_ONLY=99999]="EDITION_99999_TEST_ONLY",n[n.EDITION_MAX=2147483647]="EDITION_MAX"})(C0||(C0={}));var N0;(function(n){n[n.VISIBILITY_UNSET=0]="VISIBILITY_UNSET",n[n.VISIBILITY_LOCAL=1]="VISIBILITY_LOCAL",n[n.VISIBILITY_EXPORT=2]="VISIBILITY_EXPORT"})(N0||(N0={}));function $f(n){return Object.assign(Object.assign({readUnknownFields:!0,recursionLimit:100},n),{depth:0})}function gi(n,e,t){let i=xt(n);return qf(n).read(i,new ur(e),$f(t),e.byteLength),i}var L0=new WeakMap;function qf(n){let e=L0.get(n);return e===void 0&&(e=RE(n)),e}function RE(n){let e=String(n),t=new Map,i={read:IE(e,t),readGroup:CE(e,t)};L0.set(n,i);for(let r of n.fields)t.set(r.number,F0(r));return i}function IE(n,e){return(t,i,r,s)=>{var o;if(++r.depth>r.recursionLimit)throw new Error(`cannot decode ${n} from binary: maximum recursion depth of ${r.recursionLimit} reached`);let a=i.pos+s,l=(o=t.$unknown)!==null&&o!==void 0?o:[];for(;i.pos<a;){let[c,u]=i.tag(),h=e.get(c);if(h===void 0){let f=i.skip(u,c,r.recursionLimit-r.depth);r.readUnknownFields&&l.push({no:c,wireType:u,data:f});continue}h(t,i,r,u)}l.length>0&&(t.$unknown=l),r.depth--}}function CE(n,e){return(t,i,r,s)=>{var o;if(++r.depth>r.recursionLimit)throw new Error(`cannot decode ${n} from binary: maximum recursion depth of ${r.recursionLimit} reached`);let a,l,c=(o=t.$unknown)!==null&&o!==void 0?o:[];for(;i.pos<i.len&&([a,l]=i.tag(),l!=Gt.EndGroup);){let u=e.get(a);if(u===void 0){let h=i.skip(l,a,r.recursionLimit-r.depth);r.readUnknownFields&&c.push({no:a,wireType:l,data:h});continue}u(t,i,r,l)}if(l!=Gt.EndGroup||a!==s)throw new Error("invalid end group tag");c.length>0&&(t.$unknown=c),r.depth--}}function D0(n,e,t,i,r){F0(t)(n[Tn],e,r,i)}function F0(n){switch(n.fieldKind){case"scalar":return NE(n);case"enum":return PE(n);case"message":return LE(n);case"list":return DE(n);case"map":return FE(n)}}function NE(n){let e=sc(n.scalar,n.utf8Validation,n.longAsString),t=n.localName;if(n.oneof){let i=n.oneof.localName;return(r,s)=>{r[i]={case:t,value:e(s)}}}return(i,r)=>{i[t]=e(r)}}function PE(n){var e;let t=n.localName,i=(e=n.oneof)===null||e===void 0?void 0:e.localName;if(n.enum.open)return i!==void 0?(o,a)=>{o[i]={case:t,value:a.int32()}}:(o,a)=>{o[t]=a.int32()};let r=n.enum.values,s=n.number;return(o,a,l,c)=>{var u;let h=a.int32();if(r.some(f=>f.number===h))i!==void 0?o[i]={case:t,value:h}:o[t]=h;else if(l.readUnknownFields){let f=[];pg(h,f);let d=(u=o.$unknown)!==null&&u!==void 0?u:[];d.push({no:s,wireType:c,data:new Uint8Array(f)}),o.$unknown=d}}}function LE(n){let e=n.localName,{toMessage:t,toLocal:i}=oi(n),r=U0(n);if(n.oneof){let s=n.oneof.localName;return(o,a,l)=>{let c=o[s],u=t(c.case===e?c.value:void 0);r(u,a,l),o[s]={case:e,value:i(u)}}}return(s,o,a)=>{let l=t(s[e]);r(l,o,a),s[e]=i(l)}}function U0(n){let e=qf(n.message);if(n.delimitedEncoding){let t=n.number;return(i,r,s)=>e.readGroup(i,r,s,t)}return(t,i,r)=>e.read(t,i,r,i.uint32())}function DE(n){let e=n.localName;if(n.listKind=="message"){let{toMessage:o,toLocal:a}=oi(n),l=U0(n);return(c,u,h)=>{let f=o(void 0);l(f,u,h),c[e].push(a(f))}}let t=n.listKind=="enum"?V.INT32:n.scalar,i=n.listKind=="scalar"?n.longAsString:!1,r=sc(t,n.utf8Validation,i),s=t!=V.STRING&&t!=V.BYTES;return(o,a,l,c)=>{let u=o[e];if(c==Gt.LengthDelimited&&s){let h=a.uint32()+a.pos;for(;a.pos<h;)u.push(r(a))}else u.push(r(a))}}function FE(n){let e=n.localName,t=sc(n.mapKey,n.utf8Validation,!1),i=Zn(n.mapKey,!1),r,s;switch(n.mapKind){case"scalar":{let o=n.scalar,a=sc(o,n.utf8Validation,!1);if(r=l=>a(l),o==V.BYTES)s=()=>new Uint8Array(0);else{let l=Zn(o,!1);s=()=>l}break}case"enum":{let o=n.enum.values[0].number;r=a=>a.int32(),s=()=>o;break}case"message":{let{toMessage:o,toLocal:a}=oi(n),l=qf(n.message).read;r=(c,u,h)=>{let f=o(h);return l(f,c,u,c.uint32()),a(f)},s=()=>a(o(void 0));break}}return(o,a,l)=>{let c=o[e],u,h,f=a.uint32(),d=a.pos+f;for(;a.pos<d;){let[p,x]=a.tag();switch(p){case 1:u=t(a);break;case 2:h=r(a,l,h);break;default:a.skip(x,p,l.recursionLimit-l.depth)}}u===void 0&&(u=i),h===void 0&&(h=s()),Hn(c,u,h)}}function sc(n,e,t){switch(n){case V.STRING:return i=>i.string(e);case V.BOOL:return i=>i.bool();case V.DOUBLE:return i=>i.double();case V.FLOAT:return i=>i.float();case V.INT32:return i=>i.int32();case V.INT64:return t?i=>String(i.int64()):i=>i.int64();case V.UINT64:return t?i=>String(i.uint64()):i=>i.uint64();case V.FIXED64:return t?i=>String(i.fixed64()):i=>i.fixed64();case V.BYTES:return i=>i.bytes();case V.FIXED32:return i=>i.fixed32();case V.SFIXED32:return i=>i.sfixed32();case V.SFIXED64:return t?i=>String(i.sfixed64()):i=>i.sfixed64();case V.SINT64:return t?i=>String(i.sint64()):i=>i.sint64();case V.UINT32:return i=>i.uint32();case V.SINT32:return i=>i.sint32()}}function hr(n,e){var t;let i=gi(P0,oo(n));return i.messageType.forEach(Ca),i.dependency=(t=e?.map(s=>s.proto.name))!==null&&t!==void 0?t:[],ic(i,s=>e?.find(o=>o.proto.name===s)).getFile(i.name)}var Jf=hr("Chlnb29nbGUvcHJvdG9idWYvYW55LnByb3RvEg9nb29nbGUucHJvdG9idWYiJgoDQW55EhAKCHR5cGVfdXJsGAEgASgJEg0KBXZhbHVlGAIgASgMQnYKE2NvbS5nb29nbGUucHJvdG9idWZCCEFueVByb3RvUAFaLGdvb2dsZS5nb2xhbmcub3JnL3Byb3RvYnVmL3R5cGVzL2tub3duL2FueXBiogIDR1BCqgIeR29vZ2xlLlByb3RvYnVmLldlbGxLbm93blR5cGVzYgZwcm90bzM"),O0=vn(Jf,0);var UE=2,OE=3,B0={writeUnknownFields:!0};function BE(n){return n?Object.assign(Object.assign({},B0),n):B0}function ts(n,e,t){let i=new ro;return jf(n)(i,BE(t),e),i.finish()}var k0=new WeakMap;function jf(n){let e=k0.get(n);return e===void 0&&(e=kE(n)),e}function kE(n){let e=n.typeName,t=n.fields.concat().sort((o,a)=>o.number-a.number),i=t[0],r=[],s=(o,a,l)=>{if(l.$typeName!==e&&i!==void 0)throw new Mt(i,`cannot use ${i} with message ${l.$typeName}`,"ForeignFieldError");for(let u=0;u<r.length;u++)r[u](o,a,l);let c=l.$unknown;if(c!==void 0&&a.writeUnknownFields)for(let u=0;u<c.length;u++){let{no:h,wireType:f,data:d}=c[u];o.tag(h,f).raw(d)}};k0.set(n,s);for(let o of t)r.push(V0(o));return s}function V0(n){switch(n.fieldKind){case"message":case"scalar":case"enum":return VE(n);case"list":return zE(n);case"map":return HE(n)}}function VE(n){let e=GE(n),t=n.localName;if(n.oneof){let i=n.oneof.localName;return(r,s,o)=>{let a=o[i];a.case===t&&e(r,s,a.value)}}if(n.presence!=UE){let i=n.presence==OE?`cannot encode ${n} to binary: required field not set`:void 0;return(r,s,o)=>{let a=o[t];if(a!==void 0&&Object.prototype.hasOwnProperty.call(o,t))e(r,s,a);else if(i!==void 0)throw new Error(i)}}if(n.fieldKind=="enum"){let i=n.enum.values[0].number;return(r,s,o)=>{let a=o[t];a!==i&&e(r,s,a)}}switch(n.scalar){case V.BOOL:return(i,r,s)=>{let o=s[t];o!==!1&&e(i,r,o)};case V.STRING:return(i,r,s)=>{let o=s[t];o!==""&&e(i,r,o)};case V.BYTES:return(i,r,s)=>{let o=s[t];(!(o instanceof Uint8Array)||o.byteLength>0)&&e(i,r,o)};case V.DOUBLE:case V.FLOAT:return(i,r,s)=>{let o=s[t];Object.is(o,0)||e(i,r,o)};default:return(i,r,s)=>{let o=s[t];o!=0&&e(i,r,o)}}}function GE(n){switch(n.fieldKind){case"message":{let{toMessage:e}=oi(n),t=z0(n);return(i,r,s)=>{t(i,r,e(s))}}case"scalar":case"enum":{let e=n.fieldKind=="enum"?V.INT32:n.scalar,t=n.number,i=ac(e),r=oc(e,n.parent.typeName,n.name);return(s,o,a)=>{s.tag(t,i),r(s,a)}}}}function zE(n){let e=n.localName,t=n.number;switch(n.listKind){case"message":{let{toMessage:i}=oi(n),r=z0(n);return(s,o,a)=>{let l=a[e];for(let c=0;c<l.length;c++)r(s,o,i(l[c]))}}case"scalar":case"enum":{let i=n.listKind=="enum"?V.INT32:n.scalar,r=oc(i,n.parent.typeName,n.name);if(n.packed)return(o,a,l)=>{let c=l[e];if(c.length!=0){o.tag(t,Gt.LengthDelimited).fork();for(let u=0;u<c.length;u++)r(o,c[u]);o.join()}};let s=ac(i);return(o,a,l)=>{let c=l[e];for(let u=0;u<c.length;u++)o.tag(t,s),r(o,c[u])}}}}function HE(n){let e=n.localName,t=n.number,i=WE(n);if(n.mapKind=="message"){let{toMessage:a}=oi(n),l=jf(n.message);return(c,u,h)=>{let f=h[e],d=Object.keys(f);for(let p=0;p<d.length;p++){let x=d[p];c.tag(t,Gt.LengthDelimited).fork(),i(c,x),c.tag(2,Gt.LengthDelimited).fork(),l(c,u,a(f[x])),c.join(),c.join()}}}let r=n.mapKind=="enum"?V.INT32:n.scalar,s=ac(r),o=oc(r,n.parent.typeName,n.name);return(a,l,c)=>{let u=c[e],h=Object.keys(u);for(let f=0;f<h.length;f++){let d=h[f];a.tag(t,Gt.LengthDelimited).fork(),i(a,d),a.tag(2,s),o(a,u[d]),a.join()}}}function WE(n){let e=ac(n.mapKey),t=oc(n.mapKey,n.parent.typeName,n.name),i=XE(n.mapKey);return(r,s)=>{r.tag(1,e),t(r,i(s))}}function XE(n){switch(n){case V.STRING:return e=>e;case V.BOOL:return e=>e==="true"?!0:e==="false"?!1:e;case V.UINT64:case V.FIXED64:return e=>{try{return Et.uParse(e)}catch{return e}};case V.INT64:case V.SFIXED64:case V.SINT64:return e=>{try{return Et.parse(e)}catch{return e}};default:return e=>{let t=Number.parseInt(e);return Number.isFinite(t)?t:e}}}function oc(n,e,t){let i=YE(n);return(r,s)=>{try{i(r,s)}catch(o){throw o instanceof Error?new Error(`cannot encode field ${e}.${t} to binary: ${o.message}`):o}}}function YE(n){switch(n){case V.STRING:return(e,t)=>e.string(t);case V.BOOL:return(e,t)=>e.bool(t);case V.DOUBLE:return(e,t)=>e.double(t);case V.FLOAT:return(e,t)=>e.float(t);case V.INT32:return(e,t)=>e.int32(t);case V.INT64:return(e,t)=>e.int64(t);case V.UINT64:return(e,t)=>e.uint64(t);case V.FIXED64:return(e,t)=>e.fixed64(t);case V.BYTES:return(e,t)=>e.bytes(t);case V.FIXED32:return(e,t)=>e.fixed32(t);case V.SFIXED32:return(e,t)=>e.sfixed32(t);case V.SFIXED64:return(e,t)=>e.sfixed64(t);case V.SINT64:return(e,t)=>e.sint64(t);case V.UINT32:return(e,t)=>e.uint32(t);case V.SINT32:return(e,t)=>e.sint32(t)}}function G0(n,e,t,i){V0(i)(n,e,t[Tn])}function z0(n){let e=n.number,t=jf(n.message);return n.delimitedEncoding?(i,r,s)=>{i.tag(e,Gt.StartGroup),t(i,r,s),i.tag(e,Gt.EndGroup)}:(i,r,s)=>{i.tag(e,Gt.LengthDelimited).fork(),t(i,r,s),i.join()}}function ac(n){switch(n){case V.BYTES:case V.STRING:return Gt.LengthDelimited;case V.DOUBLE:case V.FIXED64:case V.SFIXED64:return Gt.Bit64;case V.FIXED32:case V.SFIXED32:case V.FLOAT:return Gt.Bit32;default:return Gt.Varint}}function H0(n,e,t){let i=!1;return t||(t=xt(O0),i=!0),t.value=ts(n,e),t.typeUrl=$E(e.$typeName),i?t:void 0}function KE(n,e){if(n.typeUrl==="")return!1;let t=typeof e=="string"?e:e.typeName,i=X0(n.typeUrl);return t===i}function W0(n,e){if(n.typeUrl==="")return;let t=e.kind=="message"?e:e.getMessage(X0(n.typeUrl));if(!(!t||!KE(n,t)))return gi(t,n.value)}function $E(n){return`type.googleapis.com/${n}`}function X0(n){let e=n.lastIndexOf("/"),t=e>=0?n.substring(e+1):n;if(!t.length)throw new Error(`invalid type url: ${n}`);return t}var Y0=hr("CiBnb29nbGUvcHJvdG9idWYvZmllbGRfbWFzay5wcm90bxIPZ29vZ2xlLnByb3RvYnVmIhoKCUZpZWxkTWFzaxINCgVwYXRocxgBIAMoCUKFAQoTY29tLmdvb2dsZS5wcm90b2J1ZkIORmllbGRNYXNrUHJvdG9QAVoyZ29vZ2xlLmdvbGFuZy5vcmcvcHJvdG9idWYvdHlwZXMva25vd24vZmllbGRtYXNrcGL4AQGiAgNHUEKqAh5Hb29nbGUuUHJvdG9idWYuV2VsbEtub3duVHlwZXNiBnByb3RvMw");var Qf=hr("Chxnb29nbGUvcHJvdG9idWYvc3RydWN0LnByb3RvEg9nb29nbGUucHJvdG9idWYihAEKBlN0cnVjdBIzCgZmaWVsZHMYASADKAsyIy5nb29nbGUucHJvdG9idWYuU3RydWN0LkZpZWxkc0VudHJ5GkUKC0ZpZWxkc0VudHJ5EgsKA2tleRgBIAEoCRIlCgV2YWx1ZRgCIAEoCzIWLmdvb2dsZS5wcm90b2J1Zi5WYWx1ZToCOAEi6gEKBVZhbHVlEjAKCm51bGxfdmFsdWUYASABKA4yGi5nb29nbGUucHJvdG9idWYuTnVsbFZhbHVlSAASFgoMbnVtYmVyX3ZhbHVlGAIgASgBSAASFgoMc3RyaW5nX3ZhbHVlGAMgASgJSAASFAoKYm9vbF92YWx1ZRgEIAEoCEgAEi8KDHN0cnVjdF92YWx1ZRgFIAEoCzIXLmdvb2dsZS5wcm90b2J1Zi5TdHJ1Y3RIABIwCgpsaXN0X3ZhbHVlGAYgASgLMhouZ29vZ2xlLnByb3RvYnVmLkxpc3RWYWx1ZUgAQgYKBGtpbmQiMwoJTGlzdFZhbHVlEiYKBnZhbHVlcxgBIAMoCzIWLmdvb2dsZS5wcm90b2J1Zi5WYWx1ZSobCglOdWxsVmFsdWUSDgoKTlVMTF9WQUxVRRAAQn8KE2NvbS5nb29nbGUucHJvdG9idWZCC1N0cnVjdFByb3RvUAFaL2dvb2dsZS5nb2xhbmcub3JnL3Byb3RvYnVmL3R5cGVzL2tub3duL3N0cnVjdHBi+AEBogIDR1BCqgIeR29vZ2xlLlByb3RvYnVmLldlbGxLbm93blR5cGVzYgZwcm90bzM"),Z0=vn(Qf,0),ed=vn(Qf,1),K0=vn(Qf,2),lc;(function(n){n[n.NULL_VALUE=0]="NULL_VALUE"})(lc||(lc={}));function $0(n,e,t){J0(e,n);let i=qE(n.$unknown,e),[r,s,o]=lo(e),a=$f(t);for(let l of i)D0(r,new ur(l.data),s,l.wireType,a);return o()}function q0(n,e,t){var i;J0(e,n);let r=((i=n.$unknown)!==null&&i!==void 0?i:[]).filter(c=>c.no!==e.number),[s,o]=lo(e,t),a=new ro;G0(a,{writeUnknownFields:!0},s,o);let l=new ur(a.finish());for(;l.pos<l.len;){let[c,u]=l.tag(),h=l.skip(u,c);r.push({no:c,wireType:u,data:h})}n.$unknown=r}function qE(n,e){if(n===void 0)return[];if(e.fieldKind==="enum"||e.fieldKind==="scalar"){for(let t=n.length-1;t>=0;--t)if(n[t].no==e.number)return[n[t]];return[]}return n.filter(t=>t.no===e.number)}function lo(n,e){let t=n.typeName,i=Object.assign(Object.assign({},n),{kind:"field",parent:n.extendee,localName:t}),r=Object.assign(Object.assign({},n.extendee),{fields:[i],members:[i],oneofs:[]}),s=xt(r,e!==void 0?{[t]:e}:void 0);return[Zg(r,s),i,()=>{let o=s[t];if(o===void 0){let a=n.message;return mi(a)?Zn(a.fields[0].scalar,a.fields[0].longAsString):xt(a)}return o}]}function J0(n,e){if(n.extendee.typeName!=e.$typeName)throw new Error(`extension ${n.typeName} can only be applied to message ${n.extendee.typeName}`)}var cc=Date.parse("0001-01-01T00:00:00Z"),uc=Date.parse("9999-12-31T23:59:59Z"),hc=-315576e6,fc=315576e6;var JE=3,jE=2,j0={alwaysEmitImplicit:!1,enumAsInteger:!1,useProtoFieldName:!1};function QE(n){return n?Object.assign(Object.assign({},j0),n):j0}function eM(n,e,t){return dc(n)(QE(t),e)}function e_(n,e,t){var i;let r=eM(n,e,t);return JSON.stringify(r,null,(i=t?.prettySpaces)!==null&&i!==void 0?i:0)}var td=new WeakMap;function dc(n){let e=td.get(n);return e===void 0&&(e=tM(n)),e}function tM(n){let e=n.typeName,t=iM(n);if(t!==void 0){let a=n.fields[0],l=(c,u)=>{if(u.$typeName!==e&&a!==void 0)throw new Mt(a,`cannot use ${a} with message ${u.$typeName}`,"ForeignFieldError");return t(c,u)};return td.set(n,l),l}let i=n.fields.concat().sort((a,l)=>a.number-l.number),r=i[0],s=[],o=(a,l)=>{if(l.$typeName!==e&&r!==void 0)throw new Mt(r,`cannot use ${r} with message ${l.$typeName}`,"ForeignFieldError");let c={};for(let u=0;u<s.length;u++)s[u](a,l,c);return a.registry&&cM(c,a,a.registry,l,n),c};td.set(n,o);for(let a of i){let l=rM(a);s.push(a.jsonName==="__proto__"||a.name==="__proto__"?nM(l):l)}return o}function nM(n){return(e,t,i)=>{let r=Object.create(null);n(e,t,r);for(let s of Object.keys(r))Hn(i,s,r[s])}}function iM(n){if(n.typeName.startsWith("google.protobuf."))switch(n.typeName){case"google.protobuf.Any":return(e,t)=>uM(t,e);case"google.protobuf.Timestamp":return(e,t)=>dM(t);case"google.protobuf.Duration":return(e,t)=>hM(t);case"google.protobuf.FieldMask":return(e,t)=>fM(t);case"google.protobuf.Struct":return(e,t)=>r_(t);case"google.protobuf.Value":return(e,t)=>rd(t);case"google.protobuf.ListValue":return(e,t)=>s_(t);default:if(mi(n)){let e=n.fields[0],t=e.localName,i=Zn(e.scalar,!1),r=pc(e);return(s,o)=>{let a=o[t];return r(s,a===void 0?i:a)}}return}}function rM(n){switch(n.fieldKind){case"scalar":case"enum":case"message":return sM(n);case"list":case"map":{let e=n.fieldKind=="list"?n_(n):i_(n),t=n.name,i=n.jsonName,r=n.localName;return(s,o,a)=>{let l=e(s,o[r]);l!==void 0&&(a[s.useProtoFieldName?t:i]=l)}}}}function sM(n){let e=t_(n),t=n.name,i=n.jsonName,r=n.localName;if(n.oneof){let s=n.oneof.localName;return(o,a,l)=>{let c=a[s];c.case===r&&(l[o.useProtoFieldName?t:i]=e(o,c.value))}}if(n.presence!=jE){let s=n.presence==JE?`cannot encode ${n} to JSON: required field not set`:void 0;return(o,a,l)=>{let c=a[r];if(c!==void 0&&Object.prototype.hasOwnProperty.call(a,r))l[o.useProtoFieldName?t:i]=e(o,c);else if(s!==void 0)throw new Error(s)}}if(n.fieldKind=="enum"){let s=n.enum.values[0].number;return(o,a,l)=>{let c=a[r];(c!==s||o.alwaysEmitImplicit)&&(l[o.useProtoFieldName?t:i]=e(o,c))}}switch(n.scalar){case V.BOOL:return(s,o,a)=>{let l=o[r];(l!==!1||s.alwaysEmitImplicit)&&(a[s.useProtoFieldName?t:i]=e(s,l))};case V.STRING:return(s,o,a)=>{let l=o[r];(l!==""||s.alwaysEmitImplicit)&&(a[s.useProtoFieldName?t:i]=e(s,l))};case V.BYTES:return(s,o,a)=>{let l=o[r];(!(l instanceof Uint8Array)||l.byteLength>0||s.alwaysEmitImplicit)&&(a[s.useProtoFieldName?t:i]=e(s,l))};case V.DOUBLE:case V.FLOAT:return(s,o,a)=>{let l=o[r];(!Object.is(l,0)||s.alwaysEmitImplicit)&&(a[s.useProtoFieldName?t:i]=e(s,l))};default:return(s,o,a)=>{let l=o[r];(l!=0||s.alwaysEmitImplicit)&&(a[s.useProtoFieldName?t:i]=e(s,l))}}}function oM(n){switch(n.fieldKind){case"scalar":case"enum":case"message":return t_(n);case"list":return n_(n);case"map":return i_(n)}}function t_(n){switch(n.fieldKind){case"scalar":return pc(n);case"enum":return id(n);case"message":return nd(n)}}function nd(n){let{toMessage:e}=oi(n),t=dc(n.message);return(i,r)=>t(i,e(r))}function n_(n){let e=aM(n);return(t,i)=>{let r=i;if(r.length==0&&!t.alwaysEmitImplicit)return;let s=[];for(let o=0;o<r.length;o++)s.push(e(t,r[o]));return s}}function aM(n){switch(n.listKind){case"scalar":return pc(n);case"enum":return id(n);case"message":return nd(n)}}function i_(n){let e=lM(n);return(t,i)=>{let r=i,s=Object.keys(r);if(s.length==0&&!t.alwaysEmitImplicit)return;let o={};for(let a=0;a<s.length;a++){let l=s[a];Hn(o,l,e(t,r[l]))}return o}}function lM(n){switch(n.mapKind){case"scalar":return pc(n);case"enum":return id(n);case"message":return nd(n)}}function id(n){let e=n.enum;return e.typeName=="google.protobuf.NullValue"?(t,i)=>{if(typeof i!="number")throw Q0(e,i);return null}:(t,i)=>{var r,s;if(typeof i!="number")throw Q0(e,i);return t.enumAsInteger?i:(s=(r=e.value[i])===null||r===void 0?void 0:r.jsonName)!==null&&s!==void 0?s:i}}function Q0(n,e){return new Error(`cannot encode ${n} to JSON: expected number, got ${pn(e)}`)}function pc(n){switch(n.scalar){case V.INT32:case V.SFIXED32:case V.SINT32:case V.FIXED32:case V.UINT32:return(e,t)=>{if(typeof t!="number")throw co(n,t);return t};case V.FLOAT:case V.DOUBLE:return(e,t)=>{if(typeof t!="number")throw co(n,t);return Number.isNaN(t)?"NaN":t===Number.POSITIVE_INFINITY?"Infinity":t===Number.NEGATIVE_INFINITY?"-Infinity":t};case V.STRING:return(e,t)=>{if(typeof t!="string")throw co(n,t);return t};case V.BOOL:return(e,t)=>{if(typeof t!="boolean")throw co(n,t);return t};case V.UINT64:case V.FIXED64:case V.INT64:case V.SFIXED64:case V.SINT64:return(e,t)=>{if(typeof t=="bigint"||typeof t=="string"||typeof t=="number"&&Number.isInteger(t))return t.toString();throw co(n,t)};case V.BYTES:return(e,t)=>{if(t instanceof Uint8Array)return Hf(t);throw co(n,t)}}}function co(n,e){var t;return new Error(`cannot encode ${n} to JSON: ${(t=$l(n,e))===null||t===void 0?void 0:t.message}`)}function cM(n,e,t,i,r){let s=i.$unknown;if(s===void 0)return;let o=new Set;for(let a=0;a<s.length;a++){let{no:l}=s[a];if(!o.has(l)){o.add(l);let c=t.getExtensionFor(r,l);if(!c)continue;let u=$0(i,c),[h,f]=lo(c,u),d=h[Tn],p=oM(f)(e,d[f.localName]);p!==void 0&&(n[c.jsonName]=p)}}}function uM(n,e){if(n.typeUrl==="")return{};let{registry:t}=e,i,r;if(t&&(i=W0(n,t),i&&(r=t.getMessage(i.$typeName))),!r||!i)throw new Error(`cannot encode message ${n.$typeName} to JSON: "${n.typeUrl}" is not in the type registry`);let s=Zl(r)?{value:dc(r)(e,i)}:dc(r)(e,i);return s["@type"]=n.typeUrl,s}function hM(n){let e=Number(n.seconds),t=n.nanos;if(e>fc||e<hc)throw new Error(`cannot encode message ${n.$typeName} to JSON: value out of range`);if(e>0&&t<0||e<0&&t>0)throw new Error(`cannot encode message ${n.$typeName} to JSON: nanos sign must match seconds sign`);let i=n.seconds.toString();if(t!==0){let r=Math.abs(t).toString();r="0".repeat(9-r.length)+r,r.substring(3)==="000000"?r=r.substring(0,3):r.substring(6)==="000"&&(r=r.substring(0,6)),i+="."+r,t<0&&e==0&&(i="-"+i)}return i+"s"}function fM(n){return n.paths.map(e=>{if(tc(Rr(e))!==e)throw new Error(`cannot encode message ${n.$typeName} to JSON: lowerCamelCase of path name "${e}" is irreversible`);return Rr(e)}).join(",")}function r_(n){let e={},t=Object.keys(n.fields);for(let i=0;i<t.length;i++){let r=t[i];Hn(e,r,rd(n.fields[r]))}return e}function rd(n){switch(n.kind.case){case"nullValue":return null;case"numberValue":if(!Number.isFinite(n.kind.value))throw new Error(`${n.$typeName} cannot be NaN or Infinity`);return n.kind.value;case"boolValue":return n.kind.value;case"stringValue":return n.kind.value;case"structValue":return r_(n.kind.value);case"listValue":return s_(n.kind.value);default:throw new Error(`${n.$typeName} must have a value`)}}function s_(n){return n.values.map(rd)}function dM(n){let e=Number(n.seconds)*1e3;if(e<cc||e>uc)throw new Error(`cannot encode message ${n.$typeName} to JSON: must be from 0001-01-01T00:00:00Z to 9999-12-31T23:59:59Z inclusive`);if(n.nanos<0)throw new Error(`cannot encode message ${n.$typeName} to JSON: nanos must not be negative`);if(n.nanos>999999999)throw new Error(`cannot encode message ${n.$typeName} to JSON: nanos must not be greater than 999999999`);let t="Z";if(n.nanos>0){let i=(n.nanos+1e9).toString().substring(1);i.substring(3)==="000000"?t="."+i.substring(0,3)+"Z":i.substring(6)==="000"?t="."+i.substring(0,6)+"Z":t="."+i+"Z"}return new Date(e).toISOString().replace(".000Z",t)}var pM=2;function mM(n){return Object.assign(Object.assign({ignoreUnknownFields:!1,recursionLimit:100},n),{depth:0})}function a_(n,e,t){return gM(n,AM(e,n.typeName),t)}function gM(n,e,t){let i=xt(n);return _M(n,i,e,t),i}function _M(n,e,t,i){try{uo(n)(e,t,mM(i))}catch(r){throw Dg(r)?new Error(`cannot decode ${r.field()} from JSON: ${r.message}`,{cause:r}):r}}var sd=new WeakMap;function uo(n){let e=sd.get(n);return e===void 0&&(e=yM(n)),e}function yM(n){let e=String(n),t=xM(n);if(t!==void 0){let o=(a,l,c)=>{if(++c.depth>c.recursionLimit)throw new Error(`cannot decode ${e} from JSON: maximum recursion depth of ${c.recursionLimit} reached`);t(a,l,c),c.depth--};return sd.set(n,o),o}let i=n.typeName,r=new Map,s=(o,a,l)=>{var c;if(++l.depth>l.recursionLimit)throw new Error(`cannot decode ${e} from JSON: maximum recursion depth of ${l.recursionLimit} reached`);if(a==null||Array.isArray(a)||typeof a!="object")throw new Error(`cannot decode ${e} from JSON: ${pn(a)}`);let u=new Map,h=new Set,f=Object.keys(a);for(let d=0;d<f.length;d++){let p=f[d],x=a[p],m=r.get(p);if(m!==void 0){let g=m.field;if(h.has(g))throw new Mt(g,"set multiple times");if(h.add(g),m.oneofScalarNullSkip&&x===null)continue;if(m.oneof){let b=u.get(m.oneof);if(b!==void 0)throw new Mt(m.oneof,`oneof set multiple times by ${b.name} and ${g.name}`);u.set(m.oneof,g)}m.read(o,x,l)}else{let g=p.startsWith("[")&&p.endsWith("]")?(c=l.registry)===null||c===void 0?void 0:c.getExtension(p.substring(1,p.length-1)):void 0;if(g?.extendee.typeName==i){let[b,T,v]=lo(g);o_(T)(b[Tn],x,l),q0(o,g,v())}if(g===void 0&&!l.ignoreUnknownFields)throw new Error(`cannot decode ${e} from JSON: key "${p}" is unknown`)}}l.depth--};sd.set(n,s);for(let o of n.fields){let a={read:o_(o),field:o,oneof:o.oneof,oneofScalarNullSkip:o.oneof!==void 0&&o.fieldKind=="scalar"};r.set(o.name,a).set(o.jsonName,a)}return s}function xM(n){if(n.typeName.startsWith("google.protobuf."))switch(n.typeName){case"google.protobuf.Any":return(e,t,i)=>IM(e,t,i);case"google.protobuf.Timestamp":return(e,t)=>CM(e,t);case"google.protobuf.Duration":return(e,t)=>NM(e,t);case"google.protobuf.FieldMask":return(e,t)=>PM(e,t);case"google.protobuf.Struct":return(e,t,i)=>h_(e,t,i);case"google.protobuf.Value":return(e,t,i)=>ud(e,t,i);case"google.protobuf.ListValue":return(e,t,i)=>f_(e,t,i);default:if(mi(n)){let e=n.fields[0],t=e.localName,i=e.scalar,r=e.longAsString,s=c_(e);return(o,a)=>{a===null?o[t]=Zn(i,r):o[t]=s(a)}}return}}function o_(n){switch(n.fieldKind){case"scalar":return bM(n);case"enum":return vM(n);case"message":return SM(n);case"list":return EM(n);case"map":return wM(n)}}function bM(n){let e=c_(n),t=n.localName;if(n.oneof){let r=n.oneof.localName;return(s,o)=>{s[r]={case:t,value:e(o)}}}let i=l_(n);return(r,s)=>{s===null?i(r):r[t]=e(s)}}function l_(n){let e=n.localName;if(n.presence!=pM)return r=>{delete r[e]};if(n.fieldKind=="enum"){let r=n.enum.values[0].number;return s=>{s[e]=r}}let t=n.scalar,i=n.longAsString;return r=>{r[e]=Zn(t,i)}}function vM(n){let e=od(n.enum),t=ad(n.enum),i=n.localName,r=n.enum.typeName!="google.protobuf.NullValue";if(n.oneof){let o=n.oneof.localName;return(a,l,c)=>{if(l===null&&r){a[o].case===i&&(a[o]={case:void 0});return}let u=e(l,c.ignoreUnknownFields);if(u===ho)return;let h=t(u);if(h!==!0)throw new Mt(n,Ci(n,u,h));a[o]={case:i,value:u}}}let s=l_(n);return(o,a,l)=>{if(a===null&&r){s(o);return}let c=e(a,l.ignoreUnknownFields);if(c===ho)return;let u=t(c);if(u!==!0)throw new Mt(n,Ci(n,c,u));o[i]=c}}function SM(n){let e=n.localName,{toMessage:t,toLocal:i}=oi(n),r=uo(n.message),s=n.message.typeName!="google.protobuf.Value";if(n.oneof){let o=n.oneof.localName;return(a,l,c)=>{let u=a[o];if(l===null&&s){u.case===e&&(a[o]={case:void 0});return}let h=t(u.case===e?u.value:void 0);r(h,l,c),a[o]={case:e,value:i(h)}}}return(o,a,l)=>{if(a===null&&s){delete o[e];return}let c=t(o[e]);r(c,a,l),o[e]=i(c)}}function EM(n){let e=n.localName,t=MM(n);return(i,r,s)=>{if(r===null)return;if(!Array.isArray(r))throw new Mt(n,"expected Array, got "+pn(r));let o=i[e];for(let a=0;a<r.length;a++){let l=t(r[a],s,o.length);l!==ho&&o.push(l)}}}function MM(n){switch(n.listKind){case"scalar":{let e=ld(n),t=Ar(n.scalar),i=cd(n);return(r,s,o)=>{if(r===null)throw new Mt(n,"list item must not be null");let a=e(r),l=t(a);if(l!==!0)throw new Mt(n,`list item #${o+1}: ${Ci(n,a,l)}`);return i(a)}}case"enum":{let e=od(n.enum),t=ad(n.enum),i=n.enum.typeName!="google.protobuf.NullValue";return(r,s,o)=>{if(r===null&&i)throw new Mt(n,"list item must not be null");let a=e(r,s.ignoreUnknownFields);if(a===ho)return a;let l=t(a);if(l!==!0)throw new Mt(n,`list item #${o+1}: ${Ci(n,a,l)}`);return a}}case"message":{let{toMessage:e,toLocal:t}=oi(n),i=uo(n.message),r=n.message.typeName!="google.protobuf.Value";return(s,o)=>{if(s===null&&r)throw new Mt(n,"list item must not be null");let a=e(void 0);return i(a,s,o),t(a)}}}}function wM(n){let e=n.localName,t=n.mapKey,i=TM(t),r=Ar(t),s,o,a=c=>c,l=!0;switch(n.mapKind){case"scalar":{s=ld(n),o=Ar(n.scalar),a=cd(n);break}case"enum":{let c=od(n.enum);s=(u,h)=>c(u,h.ignoreUnknownFields),o=ad(n.enum),l=n.enum.typeName!="google.protobuf.NullValue";break}case"message":{let{toMessage:c,toLocal:u}=oi(n),h=uo(n.message);l=n.message.typeName!="google.protobuf.Value",s=(f,d)=>{let p=c(void 0);return h(p,f,d),u(p)};break}}return(c,u,h)=>{if(u===null)return;if(typeof u!="object"||Array.isArray(u))throw new Mt(n,"expected object, got "+pn(u));let f=c[e],d=new Set,p=Object.keys(u);for(let x=0;x<p.length;x++){let m=p[x],g=u[m],b=i(m);if(d.has(b))throw new Mt(n,`duplicate map key "${m}"`);if(d.add(b),g===null&&l)throw new Mt(n,"map value must not be null");let T=s(g,h);if(T===ho)continue;let v=r(b);if(v!==!0)throw new Mt(n,`invalid map key: ${Ci({scalar:t},b,v)}`);if(o!==void 0){let R=o(T);if(R!==!0)throw new Mt(n,`map entry ${pn(b)}: ${Ci(n,T,R)}`)}Hn(f,b,a(T))}}}var ho=Symbol();function od(n){let e=n.values[0].number,t=new Map;for(let i of n.values)t.set(i.jsonName,i.number);for(let i of n.values)t.set(i.name,i.number);return(i,r)=>{if(i===null)return e;switch(typeof i){case"number":if(Number.isInteger(i))return i;break;case"string":{let s=t.get(i);if(s!==void 0)return s;if(r)return ho;break}}throw new Error(`cannot decode ${n} from JSON: ${pn(i)}`)}}function ad(n){if(n.open)return Ar(V.INT32);let e=n.values;return t=>e.some(i=>i.number===t)}function c_(n){let e=ld(n),t=Ar(n.scalar),i=cd(n);return r=>{let s=e(r),o=t(s);if(o!==!0)throw new Mt(n,Ci(n,s,o));return i(s)}}function ld(n){switch(n.scalar){case V.DOUBLE:case V.FLOAT:return e=>{if(e==="NaN")return NaN;if(e==="Infinity")return Number.POSITIVE_INFINITY;if(e==="-Infinity")return Number.NEGATIVE_INFINITY;if(typeof e=="number"){if(Number.isNaN(e))throw new Mt(n,"unexpected NaN number");if(!Number.isFinite(e))throw new Mt(n,"unexpected infinite number");return e}if(typeof e=="string"){if(e===""||e.trim().length!==e.length)return e;let t=Number(e);return Number.isFinite(t)?t:e}return e};case V.INT32:case V.FIXED32:case V.SFIXED32:case V.SINT32:case V.UINT32:return u_;case V.BYTES:return e=>{if(typeof e=="string"){if(e==="")return new Uint8Array(0);try{return oo(e)}catch(t){let i=t instanceof Error?t.message:String(t);throw new Mt(n,i)}}return e};default:return e=>e}}function cd(n){let e=n.fieldKind!=="map"&&n.longAsString;switch(n.scalar){case V.INT64:case V.SFIXED64:case V.SINT64:return e?t=>String(t):t=>typeof t=="string"||typeof t=="number"?Et.parse(t):t;case V.FIXED64:case V.UINT64:return e?t=>String(t):t=>typeof t=="string"||typeof t=="number"?Et.uParse(t):t;default:return t=>t}}function TM(n){switch(n){case V.BOOL:return e=>{switch(e){case"true":return!0;case"false":return!1}return e};case V.INT32:case V.FIXED32:case V.UINT32:case V.SFIXED32:case V.SINT32:return u_;case V.INT64:case V.SINT64:case V.SFIXED64:case V.UINT64:case V.FIXED64:return e=>/^-?0+$/.test(e)?"0":e.replace(/^(-?)0+(?=\d)/,"$1");default:return e=>e}}function u_(n){if(typeof n=="string"){if(n===""||n.trim().length!==n.length)return n;let e=Number(n);return Number.isNaN(e)?n:e}return n}function AM(n,e){let t;try{t=JSON.parse(n)}catch(i){let r=i instanceof Error?i.message:String(i);throw new Error(`cannot decode message ${e} from JSON: ${r}`,{cause:i})}return RM(n,e),t}function RM(n,e){let t=[],i=!1,r=0;for(;r<n.length;)switch(n[r]){case"{":t.push(new Set),i=!0,r++;break;case"[":t.push(null),i=!1,r++;break;case"}":case"]":t.pop(),i=!1,r++;break;case",":i=t[t.length-1]!=null,r++;break;case":":i=!1,r++;break;case'"':{let s=r++,o=!1;for(;r<n.length;){if(n[r]=="\\"){o=!0,r+=2;continue}if(n[r]=='"')break;r++}let a=r++,l=t[t.length-1];if(i&&l){let c=o?JSON.parse(n.substring(s,a+1)):n.substring(s+1,a);if(l.has(c))throw new Error(`cannot decode message ${e} from JSON: duplicate object key "${c}"`);l.add(c)}i=!1;break}default:r++;break}}function IM(n,e,t){var i;if(e===null||Array.isArray(e)||typeof e!="object")throw new Error(`cannot decode message ${n.$typeName} from JSON: expected object but got ${pn(e)}`);if(Object.keys(e).length==0)return;let r=e["@type"];if(typeof r!="string"||r=="")throw new Error(`cannot decode message ${n.$typeName} from JSON: "@type" is empty`);let s=r.includes("/")?r.substring(r.lastIndexOf("/")+1):r;if(!s.length)throw new Error(`cannot decode message ${n.$typeName} from JSON: "@type" is invalid`);let o=(i=t.registry)===null||i===void 0?void 0:i.getMessage(s);if(!o)throw new Error(`cannot decode message ${n.$typeName} from JSON: ${r} is not in the type registry`);let a=xt(o);if(Zl(o)&&Object.prototype.hasOwnProperty.call(e,"value"))uo(o)(a,e.value,t);else{let l={};for(let c of Object.keys(e))c!=="@type"&&Hn(l,c,e[c]);uo(o)(a,l,t)}H0(o,a,n)}function CM(n,e){if(typeof e!="string")throw new Error(`cannot decode message ${n.$typeName} from JSON: ${pn(e)}`);let t=e.match(/^([0-9]{4})-([0-9]{2})-([0-9]{2})T([0-9]{2}):([0-9]{2}):([0-9]{2})(?:\.([0-9]{1,9}))?(?:Z|([+-][0-9][0-9]:[0-9][0-9]))$/);if(!t)throw new Error(`cannot decode message ${n.$typeName} from JSON: invalid RFC 3339 string`);let i=Date.parse(t[1]+"-"+t[2]+"-"+t[3]+"T"+t[4]+":"+t[5]+":"+t[6]+(t[8]?t[8]:"Z"));if(Number.isNaN(i))throw new Error(`cannot decode message ${n.$typeName} from JSON: invalid RFC 3339 string`);if(i<cc||i>uc)throw new Error(`cannot decode message ${n.$typeName} from JSON: must be from 0001-01-01T00:00:00Z to 9999-12-31T23:59:59Z inclusive`);n.seconds=Et.parse(i/1e3),n.nanos=0,t[7]&&(n.nanos=parseInt("1"+t[7]+"0".repeat(9-t[7].length))-1e9)}function NM(n,e){if(typeof e!="string")throw new Error(`cannot decode message ${n.$typeName} from JSON: ${pn(e)}`);let t=e.match(/^(-?[0-9]+)(?:\.([0-9]+))?s/);if(t===null)throw new Error(`cannot decode message ${n.$typeName} from JSON: ${pn(e)}`);let i=Number(t[1]);if(i>fc||i<hc)throw new Error(`cannot decode message ${n.$typeName} from JSON: ${pn(e)}`);if(n.seconds=Et.parse(i),typeof t[2]!="string")return;let r=t[2]+"0".repeat(9-t[2].length);n.nanos=parseInt(r),(i<0||Object.is(i,-0))&&(n.nanos=-n.nanos)}function PM(n,e){if(typeof e!="string")throw new Error(`cannot decode message ${n.$typeName} from JSON: ${pn(e)}`);e!==""&&(n.paths=e.split(",").map(t=>{if(t.includes("_"))throw new Error(`cannot decode message ${n.$typeName} from JSON: path names must be lowerCamelCase`);return tc(t)}))}function h_(n,e,t){if(typeof e!="object"||e==null||Array.isArray(e))throw new Error(`cannot decode message ${n.$typeName} from JSON ${pn(e)}`);let i=Object.keys(e);for(let r=0;r<i.length;r++){let s=i[r],o=xt(ed);ud(o,e[s],t),Hn(n.fields,s,o)}}function ud(n,e,t){if(++t.depth>t.recursionLimit)throw new Error(`cannot decode ${n.$typeName} from JSON: maximum recursion depth of ${t.recursionLimit} reached`);switch(typeof e){case"number":n.kind={case:"numberValue",value:e};break;case"string":n.kind={case:"stringValue",value:e};break;case"boolean":n.kind={case:"boolValue",value:e};break;case"object":if(e===null)n.kind={case:"nullValue",value:lc.NULL_VALUE};else if(Array.isArray(e)){let i=xt(K0);f_(i,e,t),n.kind={case:"listValue",value:i}}else{let i=xt(Z0);h_(i,e,t),n.kind={case:"structValue",value:i}}break;default:throw new Error(`cannot decode message ${n.$typeName} from JSON ${pn(e)}`)}return t.depth--,n}function f_(n,e,t){if(!Array.isArray(e))throw new Error(`cannot decode message ${n.$typeName} from JSON ${pn(e)}`);for(let i=0;i<e.length;i++){let r=xt(ed);ud(r,e[i],t),n.values.push(r)}}var We;(function(n){n[n.Canceled=1]="Canceled",n[n.Unknown=2]="Unknown",n[n.InvalidArgument=3]="InvalidArgument",n[n.DeadlineExceeded=4]="DeadlineExceeded",n[n.NotFound=5]="NotFound",n[n.AlreadyExists=6]="AlreadyExists",n[n.PermissionDenied=7]="PermissionDenied",n[n.ResourceExhausted=8]="ResourceExhausted",n[n.FailedPrecondition=9]="FailedPrecondition",n[n.Aborted=10]="Aborted",n[n.OutOfRange=11]="OutOfRange",n[n.Unimplemented=12]="Unimplemented",n[n.Internal=13]="Internal",n[n.Unavailable=14]="Unavailable",n[n.DataLoss=15]="DataLoss",n[n.Unauthenticated=16]="Unauthenticated"})(We||(We={}));function hd(n){let e=We[n];return typeof e!="string"?n.toString():e[0].toLowerCase()+e.substring(1).replace(/[A-Z]/g,t=>"_"+t.toLowerCase())}var dt=class n extends Error{constructor(e,t=We.Unknown,i,r,s){super(LM(e,t)),this.name="ConnectError",Object.setPrototypeOf(this,new.target.prototype),this.rawMessage=e,this.code=t,this.metadata=new Headers(i??{}),this.details=r??[],this.cause=s}static from(e,t=We.Unknown){return e instanceof n?e:e instanceof Error?e.name=="AbortError"||e.name=="TimeoutError"?new n(e.message,We.Canceled):new n(e.message,t,void 0,void 0,e):new n(String(e),t,void 0,void 0,e)}static[Symbol.hasInstance](e){return e instanceof Error?Object.getPrototypeOf(e)===n.prototype?!0:e.name==="ConnectError"&&"code"in e&&typeof e.code=="number"&&"metadata"in e&&"details"in e&&Array.isArray(e.details)&&"rawMessage"in e&&typeof e.rawMessage=="string"&&"cause"in e:!1}findDetails(e){let t=e.kind==="message"?{getMessage:r=>r===e.typeName?e:void 0}:e,i=[];for(let r of this.details){if("desc"in r){t.getMessage(r.desc.typeName)&&i.push(xt(r.desc,r.value));continue}let s=t.getMessage(r.type);if(s)try{i.push(gi(s,r.value))}catch{}}return i}};function LM(n,e){return n.length?`[${hd(e)}] ${n}`:`[${hd(e)}]`}function d_(n,e,t){try{let i=oo(n);return e?gi(e,i,t):i}catch(i){throw dt.from(i,We.DataLoss)}}function p_(n,e){let t={};for(let i of n.methods){let r=e(i);r!=null&&(t[i.localName]=r)}return t}var mc=1;function m_(n,e,t=!1){if(e>n){let i=`message size is larger than configured readMaxBytes ${n}`;throw t&&(i=`message size ${e} is larger than configured readMaxBytes ${n}`),new dt(i,We.ResourceExhausted)}}function DM(n){return new fd(n)}var fd=class{constructor(e){this.readMaxBytes=e,this.header=new Uint8Array(5),this.headerView=new DataView(this.header.buffer),this.buf=[]}get byteLength(){return this.buf.reduce((e,t)=>e+t.byteLength,0)}decode(e){this.buf.push(e);let t=[];for(;;){let i=this.pop();if(!i)break;t.push(i)}return t}pop(){if(!(!this.env&&(this.env=this.head(),!this.env))&&this.cons(this.env.data)){let e=this.env;return this.env=void 0,e}}head(){if(!this.cons(this.header))return;let e=this.headerView.getUint8(0),t=this.headerView.getUint32(1);return m_(this.readMaxBytes,t,!0),{flags:e,data:new Uint8Array(t)}}cons(e){let t=e.byteLength;if(this.byteLength<t)return!1;let i=0;for(;i<t;){let r=this.buf.shift();r.byteLength>t-i?(e.set(r.subarray(0,t-i),i),this.buf.unshift(r.subarray(t-i)),i+=t-i):(e.set(r,i),i+=r.byteLength)}return!0}};function gc(n){let e,t=DM(4294967295);return new ReadableStream({start(){e=n.getReader()},async pull(i){let r=!1;for(;!r;){let s=await e.read();if(s.done)t.byteLength>0&&i.error(new dt("protocol error: incomplete envelope",We.InvalidArgument)),i.close();else for(let o of t.decode(s.value))i.enqueue(o),r=!0}}})}function _c(n,e){let t=new Uint8Array(e.length+5);t.set(e,5);let i=new DataView(t.buffer,t.byteOffset,t.byteLength);return i.setUint8(0,n),i.setUint32(1,e.length),t}var FM=function(n){if(!Symbol.asyncIterator)throw new TypeError("Symbol.asyncIterator is not defined.");var e=n[Symbol.asyncIterator],t;return e?e.call(n):(n=typeof __values=="function"?__values(n):n[Symbol.iterator](),t={},i("next"),i("throw"),i("return"),t[Symbol.asyncIterator]=function(){return this},t);function i(s){t[s]=n[s]&&function(o){return new Promise(function(a,l){o=n[s](o),r(a,l,o.done,o.value)})}}function r(s,o,a,l){Promise.resolve(l).then(function(c){s({value:c,done:a})},o)}},La=function(n){return this instanceof La?(this.v=n,this):new La(n)},UM=function(n,e,t){if(!Symbol.asyncIterator)throw new TypeError("Symbol.asyncIterator is not defined.");var i=t.apply(n,e||[]),r,s=[];return r=Object.create((typeof AsyncIterator=="function"?AsyncIterator:Object).prototype),a("next"),a("throw"),a("return",o),r[Symbol.asyncIterator]=function(){return this},r;function o(d){return function(p){return Promise.resolve(p).then(d,h)}}function a(d,p){i[d]&&(r[d]=function(x){return new Promise(function(m,g){s.push([d,x,m,g])>1||l(d,x)})},p&&(r[d]=p(r[d])))}function l(d,p){try{c(i[d](p))}catch(x){f(s[0][3],x)}}function c(d){d.value instanceof La?Promise.resolve(d.value.v).then(u,h):f(s[0][2],d)}function u(d){l("next",d)}function h(d){l("throw",d)}function f(d,p){d(p),s.shift(),s.length&&l(s[0][0],s[0][1])}},OM=function(n){var e,t;return e={},i("next"),i("throw",function(r){throw r}),i("return"),e[Symbol.iterator]=function(){return this},e;function i(r,s){e[r]=n[r]?function(o){return(t=!t)?{value:La(n[r](o)),done:!1}:s?s(o):o}:s}};function g_(n){return UM(this,arguments,function*(){yield La(yield*OM(FM(n)))})}var __=function(n){if(!Symbol.asyncIterator)throw new TypeError("Symbol.asyncIterator is not defined.");var e=n[Symbol.asyncIterator],t;return e?e.call(n):(n=typeof __values=="function"?__values(n):n[Symbol.iterator](),t={},i("next"),i("throw"),i("return"),t[Symbol.asyncIterator]=function(){return this},t);function i(s){t[s]=n[s]&&function(o){return new Promise(function(a,l){o=n[s](o),r(a,l,o.done,o.value)})}}function r(s,o,a,l){Promise.resolve(l).then(function(c){s({value:c,done:a})},o)}},fo=function(n){return this instanceof fo?(this.v=n,this):new fo(n)},BM=function(n){var e,t;return e={},i("next"),i("throw",function(r){throw r}),i("return"),e[Symbol.iterator]=function(){return this},e;function i(r,s){e[r]=n[r]?function(o){return(t=!t)?{value:fo(n[r](o)),done:!1}:s?s(o):o}:s}},kM=function(n,e,t){if(!Symbol.asyncIterator)throw new TypeError("Symbol.asyncIterator is not defined.");var i=t.apply(n,e||[]),r,s=[];return r=Object.create((typeof AsyncIterator=="function"?AsyncIterator:Object).prototype),a("next"),a("throw"),a("return",o),r[Symbol.asyncIterator]=function(){return this},r;function o(d){return function(p){return Promise.resolve(p).then(d,h)}}function a(d,p){i[d]&&(r[d]=function(x){return new Promise(function(m,g){s.push([d,x,m,g])>1||l(d,x)})},p&&(r[d]=p(r[d])))}function l(d,p){try{c(i[d](p))}catch(x){f(s[0][3],x)}}function c(d){d.value instanceof fo?Promise.resolve(d.value.v).then(u,h):f(s[0][2],d)}function u(d){l("next",d)}function h(d){l("throw",d)}function f(d,p){d(p),s.shift(),s.length&&l(s[0][0],s[0][1])}};function dd(n,e){return p_(n,t=>{switch(t.methodKind){case"unary":return VM(e,t);case"server_streaming":return GM(e,t);case"client_streaming":return zM(e,t);case"bidi_streaming":return HM(e,t);default:return null}})}function VM(n,e){return async(t,i)=>{var r,s;let o=await n.unary(e,i?.signal,i?.timeoutMs,i?.headers,t,i?.contextValues);return(r=i?.onHeader)===null||r===void 0||r.call(i,o.header),(s=i?.onTrailer)===null||s===void 0||s.call(i,o.trailer),o.message}}function GM(n,e){return(t,i)=>y_(n.stream(e,i?.signal,i?.timeoutMs,i?.headers,g_([t]),i?.contextValues),i)}function zM(n,e){return async(t,i)=>{var r,s,o,a,l,c;let u=await n.stream(e,i?.signal,i?.timeoutMs,i?.headers,t,i?.contextValues);(l=i?.onHeader)===null||l===void 0||l.call(i,u.header);let h,f=0;try{for(var d=!0,p=__(u.message),x;x=await p.next(),r=x.done,!r;d=!0)a=x.value,d=!1,h=a,f++}catch(m){s={error:m}}finally{try{!d&&!r&&(o=p.return)&&await o.call(p)}finally{if(s)throw s.error}}if(!h)throw new dt("protocol error: missing response message",We.Unimplemented);if(f>1)throw new dt("protocol error: received extra messages for client streaming method",We.Unimplemented);return(c=i?.onTrailer)===null||c===void 0||c.call(i,u.trailer),h}}function HM(n,e){return(t,i)=>y_(n.stream(e,i?.signal,i?.timeoutMs,i?.headers,t,i?.contextValues),i)}function y_(n,e){let t=(function(){return kM(this,arguments,function*(){var i,r;let s=yield fo(n);(i=e?.onHeader)===null||i===void 0||i.call(e,s.header),yield fo(yield*BM(__(s.message))),(r=e?.onTrailer)===null||r===void 0||r.call(e,s.trailer)})})()[Symbol.asyncIterator]();return{[Symbol.asyncIterator]:()=>({next:()=>t.next()})}}function x_(...n){let e=new AbortController,t=n.filter(r=>r!==void 0).concat(e.signal);for(let r of t){if(r.aborted){i.apply(r);break}r.addEventListener("abort",i)}function i(){e.signal.aborted||e.abort(pd(this));for(let r of t)r.removeEventListener("abort",i)}return e}function b_(n){let e=new AbortController,t=()=>{e.abort(new dt("the operation timed out",We.DeadlineExceeded))},i;return n!==void 0&&(n<=0?t():i=setTimeout(t,n)),{signal:e.signal,cleanup:()=>clearTimeout(i)}}function pd(n){if(!n.aborted)return;if(n.reason!==void 0)return n.reason;let e=new Error("This operation was aborted");return e.name="AbortError",e}function yc(){return{get(n){return n.id in this?this[n.id]:n.defaultValue},set(n,e){return this[n.id]=e,this},delete(n){return delete this[n.id],this}}}function xc(n){let e=new Headers,t=new TextDecoder().decode(n).split(`\r
`);for(let i of t){if(i==="")continue;let r=i.indexOf(":");if(r>0){let s=i.substring(0,r).trim(),o=i.substring(r+1).trim();e.append(s,o)}}return e}var md="Content-Type";var gd="Grpc-Timeout",Hi="Grpc-Status",Da="Grpc-Message",_d="Grpc-Status-Details-Bin";var bc="User-Agent";var yd="X-User-Agent",S_="X-Grpc-Web";var E_="application/grpc-web+proto",M_="application/grpc-web+json";function w_(n,e,...t){if(t.length>0)throw new Error;return n.services[e]}var XM=hr("CgxzdGF0dXMucHJvdG8SCmdvb2dsZS5ycGMiTgoGU3RhdHVzEgwKBGNvZGUYASABKAUSDwoHbWVzc2FnZRgCIAEoCRIlCgdkZXRhaWxzGAMgAygLMhQuZ29vZ2xlLnByb3RvYnVmLkFueUJeCg5jb20uZ29vZ2xlLnJwY0ILU3RhdHVzUHJvdG9QAVo3Z29vZ2xlLmdvbGFuZy5vcmcvZ2VucHJvdG8vZ29vZ2xlYXBpcy9ycGMvc3RhdHVzO3N0YXR1c6ICA1JQQ2IGcHJvdG8z",[Jf]),T_=vn(XM,0);var A_="0";function vc(n){var e;let t=n.get(_d);if(t!=null){let r=d_(t,T_);if(r.code==0)return;let s=new dt(r.message,r.code,n);return s.details=r.details.map(o=>({type:o.typeUrl.substring(o.typeUrl.lastIndexOf("/")+1),value:o.value})),s}let i=n.get(Hi);if(i!=null){if(i===A_)return;let r=parseInt(i,10);return r in We?new dt(decodeURIComponent((e=n.get(Da))!==null&&e!==void 0?e:""),r,n):new dt(`invalid grpc-status: ${i}`,We.Internal,n)}}function Sc(n,e){return n.toString().replace(/\/?$/,`/${e.parent.typeName}/${e.name}`)}function xd(n,e){return xt(n,e)}function R_(n,e){function t(i){return i.done===!0?i:{done:i.done,value:xd(n,i.value)}}return{[Symbol.asyncIterator](){let i=e[Symbol.asyncIterator](),r={next:()=>i.next().then(t)};return i.throw!==void 0&&(r.throw=s=>i.throw(s).then(t)),i.return!==void 0&&(r.return=s=>i.return(s).then(t)),r}}}function bd(n,e){if(!e)return n;for(let t of e.concat().reverse())n=t(n);return n}function N_(n){var e;let t=Object.assign({},n);return(e=t.ignoreUnknownFields)!==null&&e!==void 0||(t.ignoreUnknownFields=!0),t}function Ec(n,e,t,i){let r=e?I_(n.input,i):C_(n.input,t);return{parse:(e?I_(n.output,i):C_(n.output,t)).parse,serialize:r.serialize}}function I_(n,e){return{parse(t){try{return gi(n,t,e)}catch(i){let r=i instanceof Error?i.message:String(i);throw new dt(`parse binary: ${r}`,We.Internal)}},serialize(t){try{return ts(n,t,e)}catch(i){let r=i instanceof Error?i.message:String(i);throw new dt(`serialize binary: ${r}`,We.Internal)}}}}function C_(n,e){var t,i;let r=(t=e?.textEncoder)!==null&&t!==void 0?t:new TextEncoder,s=(i=e?.textDecoder)!==null&&i!==void 0?i:new TextDecoder,o=N_(e);return{parse(a){try{let l=s.decode(a);return a_(n,l,o)}catch(l){throw dt.from(l,We.InvalidArgument)}},serialize(a){try{let l=e_(n,a,o);return r.encode(l)}catch(l){throw dt.from(l,We.Internal)}}}}function vd(n){let e=bd(n.next,n.interceptors),[t,i,r]=P_(n),s=Object.assign(Object.assign({},n.req),{message:xd(n.req.method.input,n.req.message),signal:t});return e(s).then(o=>(r(),o),i)}function Sd(n){let e=bd(n.next,n.interceptors),[t,i,r]=P_(n),s=Object.assign(Object.assign({},n.req),{message:R_(n.req.method.input,n.req.message),signal:t}),o=!1;return t.addEventListener("abort",function(){var a,l;let c=n.req.message[Symbol.asyncIterator]();o||(a=c.throw)===null||a===void 0||a.call(c,this.reason).catch(()=>{}),(l=c.return)===null||l===void 0||l.call(c).catch(()=>{})}),e(s).then(a=>Object.assign(Object.assign({},a),{message:{[Symbol.asyncIterator](){let l=a.message[Symbol.asyncIterator]();return{next(){return l.next().then(c=>(c.done==!0&&(o=!0,r()),c),i)}}}}}),i)}function P_(n){let{signal:e,cleanup:t}=b_(n.timeoutMs),i=x_(n.signal,e);return[i.signal,function(s){let o=i.signal.aborted?dt.from(pd(i.signal),We.Canceled):dt.from(s);return i.abort(o),t(),Promise.reject(o)},function(){t(),i.abort()}]}var fr=hr("ChZmb3ZlYWwvdjEvZm92ZWFsLnByb3RvEglmb3ZlYWwudjEijQEKCkdhemVTYW1wbGUSFgoOdHJhY2tlcl90aW1lX3MYASABKAESCQoBeBgCIAEoARIJCgF5GAMgASgBEhAKCHZhbGlkaXR5GAQgASgCEhsKA2V5ZRgFIAEoDjIOLmZvdmVhbC52MS5FeWUSFQoIZml4YXRpb24YBiABKAhIAIgBAUILCglfZml4YXRpb24iPwoPU2FtcGxlUmVqZWN0aW9uEg0KBWluZGV4GAEgASgEEg0KBWZpZWxkGAIgASgJEg4KBnJlYXNvbhgDIAEoCSKbAQoRU3RyZWFtR2F6ZVN1bW1hcnkSEAoIYWNjZXB0ZWQYASABKAQSEAoIcmVqZWN0ZWQYAiABKAQSLgoKcmVqZWN0aW9ucxgDIAMoCzIaLmZvdmVhbC52MS5TYW1wbGVSZWplY3Rpb24SHAoUbGFzdF9hY2NlcHRlZF90aW1lX3MYBCABKAESFAoMcmF0ZV9saW1pdGVkGAUgASgEIkkKD1B1c2hHYXplUmVxdWVzdBImCgdzYW1wbGVzGAEgAygLMhUuZm92ZWFsLnYxLkdhemVTYW1wbGUSDgoGc291cmNlGAIgASgJIpoBChBQdXNoR2F6ZVJlc3BvbnNlEhAKCGFjY2VwdGVkGAEgASgEEhAKCHJlamVjdGVkGAIgASgEEi4KCnJlamVjdGlvbnMYAyADKAsyGi5mb3ZlYWwudjEuU2FtcGxlUmVqZWN0aW9uEhwKFGxhc3RfYWNjZXB0ZWRfdGltZV9zGAQgASgBEhQKDHJhdGVfbGltaXRlZBgFIAEoBCJxChJXYXRjaEZyYW1lc1JlcXVlc3QSDwoHZXZlcnlfaxgBIAEoDRIVCg1pbmNsdWRlX3Bvc2VzGAIgASgIEhcKD3F1YW50aXNlZF9wb3NlcxgDIAEoCBIaChJpbmNsdWRlX2NvbGxpc2lvbnMYBCABKAgiRgoHUmF3R2F6ZRIJCgF4GAEgASgBEgkKAXkYAiABKAESDQoFYWdlX3MYAyABKAESFgoOdHJhY2tlcl90aW1lX3MYBCABKAEiswEKCEZpeGF0aW9uEgkKAXgYASABKAESCQoBeRgCIAEoARINCgVhZ2VfcxgDIAEoARIpCgZzb3VyY2UYBCABKA4yGS5mb3ZlYWwudjEuRml4YXRpb25Tb3VyY2USHwoDcmF3GAUgASgLMhIuZm92ZWFsLnYxLlJhd0dhemUSIwoFdHJhY2sYBiABKA4yFC5mb3ZlYWwudjEuR2F6ZVRyYWNrEhEKCXdpZGVuX2RlZxgHIAEoASKXAQoMQXVkaXRNZXRyaWNzEhwKFHRydWVfZmFsc2VfcG9zaXRpdmVzGAEgASgEEiEKGXRydWVfZ2VvbWV0cmljX2luYWNjdXJhY3kYAiABKAESIQoZdHJ1ZV9wZXJjZWl2ZWRfaW5hY2N1cmFjeRgDIAEoARIjCht0cnVlX2ZvdmVhbF9mYWxzZV9wb3NpdGl2ZXMYBCABKAQi5AMKDEZyYW1lTWV0cmljcxIYChBjb2xsaXNpb25fdGltZV9zGAEgASgBEhwKFGdlb21ldHJpY19pbmFjY3VyYWN5GAIgASgBEhwKFHBlcmNlaXZlZF9pbmFjY3VyYWN5GAMgASgBEhcKD2NhbmRpZGF0ZV9wYWlycxgEIAEoBBIXCg9yZWFsX2NvbGxpc2lvbnMYBSABKAQSHgoWZGVlbWVkX2F0X2ludGVycnVwdGlvbhgGIAEoBBIaChJyZXNvbHZlZF9wZXJfbGV2ZWwYByADKAQSFAoMc3BoZXJlX3Rlc3RzGAggASgEEhgKEGJ1ZGdldF9leGhhdXN0ZWQYCSABKAgSKwoFYXVkaXQYCiABKAsyFy5mb3ZlYWwudjEuQXVkaXRNZXRyaWNzSACIAQESFgoObWV0cmljc19zdHJpZGUYCyABKA0SHwoXZ2VvbWV0cmljX2luYWNjdXJhY3lfc2UYDCABKAESHwoXcGVyY2VpdmVkX2luYWNjdXJhY3lfc2UYDSABKAESIgoaYnVkZ2V0X3NwZW50X2JlZm9yZV9uYXJyb3cYDiABKAgSFAoMZm92ZWFsX3BhaXJzGA8gASgEEhUKDWZvdmVhbF9kZWVtZWQYECABKARCCAoGX2F1ZGl0IpcBCgxQaGFzZVByb2ZpbGUSEwoLaW50ZWdyYXRlX3MYASABKAESDwoHYnJvYWRfcxgCIAEoARIQCghuYXJyb3dfcxgDIAEoARISCgpyZXNwb25zZV9zGAQgASgBEhQKDHByaW9yaXRpc2VfcxgFIAEoARIRCgltZWFzdXJlX3MYBiABKAESEgoKcmVudW1iZXJfcxgHIAEoASJhCgVQb3NlcxIRCglwb3NpdGlvbnMYASABKAwSFAoMb3JpZW50YXRpb25zGAIgASgMEh8KBm9yaWdpbhgDIAEoCzIPLmZvdmVhbC52MS5WZWMzEg4KBmJvZGllcxgEIAEoDSJ6Cg5RdWFudGlzZWRQb3NlcxIRCglwb3NpdGlvbnMYASABKAwSFAoMb3JpZW50YXRpb25zGAIgASgMEh8KBm9yaWdpbhgDIAEoCzIPLmZvdmVhbC52MS5WZWMzEg4KBmV4dGVudBgEIAEoARIOCgZib2RpZXMYBSABKA0iQAoKQ29sbGlzaW9ucxIMCgRyZWFsGAEgASgMEg4KBmRlZW1lZBgCIAEoDBIUCgxkZWVtZWRfdHJ1dGgYAyABKAwiJwoEVmVjMxIJCgF4GAEgASgBEgkKAXkYAiABKAESCQoBehgDIAEoASK4AwoFRnJhbWUSDQoFaW5kZXgYASABKAQSEgoKc2ltX3RpbWVfcxgCIAEoARIlCghmaXhhdGlvbhgDIAEoCzITLmZvdmVhbC52MS5GaXhhdGlvbhIoCgdtZXRyaWNzGAQgASgLMhcuZm92ZWFsLnYxLkZyYW1lTWV0cmljcxIoCgdwcm9maWxlGAUgASgLMhcuZm92ZWFsLnYxLlBoYXNlUHJvZmlsZRIWCg5kcm9wcGVkX2JlZm9yZRgGIAEoBBIkCgVwb3NlcxgHIAEoCzIQLmZvdmVhbC52MS5Qb3Nlc0gAiAEBEjcKD3F1YW50aXNlZF9wb3NlcxgIIAEoCzIZLmZvdmVhbC52MS5RdWFudGlzZWRQb3Nlc0gBiAEBEi4KCmNvbGxpc2lvbnMYCSABKAsyFS5mb3ZlYWwudjEuQ29sbGlzaW9uc0gCiAEBEi4KCmNvbXBhcmlzb24YCiABKAsyFS5mb3ZlYWwudjEuQ29tcGFyaXNvbkgDiAEBQggKBl9wb3Nlc0ISChBfcXVhbnRpc2VkX3Bvc2VzQg0KC19jb2xsaXNpb25zQg0KC19jb21wYXJpc29uIu0BCgpDb21wYXJpc29uEiQKCGNvbGxpZGVyGAEgASgOMhIuZm92ZWFsLnYxLkNvbXBhcmUSKAoHbWV0cmljcxgCIAEoCzIXLmZvdmVhbC52MS5GcmFtZU1ldHJpY3MSDQoFcnVuX3MYAyABKAESLgoKY29sbGlzaW9ucxgEIAEoCzIVLmZvdmVhbC52MS5Db2xsaXNpb25zSACIAQESKwoKbWFpbl9hdWRpdBgFIAEoCzIXLmZvdmVhbC52MS5BdWRpdE1ldHJpY3MSFAoMYXVkaXRfc3RyaWRlGAYgASgNQg0KC19jb2xsaXNpb25zIg0KC0V4YWN0QnVkZ2V0Ip4BCgZCdWRnZXQSJwoFZXhhY3QYASABKAsyFi5mb3ZlYWwudjEuRXhhY3RCdWRnZXRIABIbChFpbnRlcnJ1cHRfYXRfemVybxgCIAEoCEgAEhEKB3dhbGxfbXMYAyABKAFIABIWCgxzcGhlcmVfdGVzdHMYBCABKARIABIbChFmcmFjdGlvbl9vZl9leGFjdBgFIAEoAUgAQgYKBGtpbmQiCQoHTW9kZWxGMSIUCgdNb2RlbEYyEgkKAWMYASABKAEiLAoMTW9kZWxGMlJhbmdlEg0KBWNfbWluGAEgASgBEg0KBWNfbWF4GAIgASgBIkUKB01vZGVsRjMSCgoCYzEYASABKAESCgoCYzIYAiABKAESCgoCYzMYAyABKAESCgoCZTEYBCABKAESCgoCZTIYBSABKAEi5QEKD1BlcmNlcHR1YWxNb2RlbBIgCgJmMRgBIAEoCzISLmZvdmVhbC52MS5Nb2RlbEYxSAASIAoCZjIYAiABKAsyEi5mb3ZlYWwudjEuTW9kZWxGMkgAEiAKAmYzGAMgASgLMhIuZm92ZWFsLnYxLk1vZGVsRjNIABIrCghmMl9yYW5nZRgFIAEoCzIXLmZvdmVhbC52MS5Nb2RlbEYyUmFuZ2VIABI2ChFlY2NlbnRyaWNpdHlfdW5pdBgEIAEoDjIbLmZvdmVhbC52MS5FY2NlbnRyaWNpdHlVbml0QgcKBW1vZGVsImAKB0Rpc3BsYXkSEAoId2lkdGhfcHgYASABKA0SEQoJaGVpZ2h0X3B4GAIgASgNEhMKC2RpYWdvbmFsX2luGAMgASgBEhsKE3ZpZXdpbmdfZGlzdGFuY2VfY20YBCABKAEirgQKC1NjZW5lQ29uZmlnEg4KBmJvZGllcxgBIAEoDRIMCgRzZWVkGAIgASgEEg8KB2RlbnNpdHkYAyABKAESFAoMc2hhcGVfcmFkaXVzGAQgASgBEg0KBWRlcHRoGAUgASgNEgwKBGR0X3MYBiABKAESEQoJbWluX3NwZWVkGAcgASgBEhEKCW1heF9zcGVlZBgIIAEoARIQCghtYXhfc3BpbhgJIAEoARInCglzY2hlZHVsZXIYCiABKA4yFC5mb3ZlYWwudjEuU2NoZWR1bGVyEiIKGmVjY2VudHJpY2l0eV90aHJlc2hvbGRfZGVnGAsgASgBEiEKBmJ1ZGdldBgMIAEoCzIRLmZvdmVhbC52MS5CdWRnZXQSMgoOc2NoZWR1bGVfbW9kZWwYDSABKAsyGi5mb3ZlYWwudjEuUGVyY2VwdHVhbE1vZGVsEjEKDW1lYXN1cmVfbW9kZWwYDiABKAsyGi5mb3ZlYWwudjEuUGVyY2VwdHVhbE1vZGVsEg0KBWF1ZGl0GA8gASgIEhUKDWZyYW1lX3JhdGVfaHoYECABKAESIwoHZGlzcGxheRgRIAEoCzISLmZvdmVhbC52MS5EaXNwbGF5Eh8KBXRydXRoGBIgASgOMhAuZm92ZWFsLnYxLlRydXRoEiMKB2NvbXBhcmUYEyABKA4yEi5mb3ZlYWwudjEuQ29tcGFyZRIdCgR0cmVlGBQgASgOMg8uZm92ZWFsLnYxLlRyZWUiEQoPR2V0U2NlbmVSZXF1ZXN0InIKBlNwaGVyZRIJCgF4GAEgASgCEgkKAXkYAiABKAISCQoBehgDIAEoAhIOCgZyYWRpdXMYBCABKAISDQoFbGV2ZWwYBSABKA0SEwoLZmlyc3RfY2hpbGQYBiABKA0SEwoLY2hpbGRfY291bnQYByABKA0iSwoKU3BoZXJlVHJlZRIiCgdzcGhlcmVzGAEgAygLMhEuZm92ZWFsLnYxLlNwaGVyZRIZChFzcGhlcmVzX3Blcl9sZXZlbBgCIAMoDSJqCgZDYW1lcmESHAoDZXllGAEgASgLMg8uZm92ZWFsLnYxLlZlYzMSHwoGdGFyZ2V0GAIgASgLMg8uZm92ZWFsLnYxLlZlYzMSEQoJZm92X3lfZGVnGAMgASgBEg4KBmFzcGVjdBgEIAEoASLjAQoQU2NlbmVEZXNjcmlwdGlvbhImCgZjb25maWcYASABKAsyFi5mb3ZlYWwudjEuU2NlbmVDb25maWcSEwoLdm9sdW1lX3NpZGUYAiABKAESJgoNdm9sdW1lX29yaWdpbhgDIAEoCzIPLmZvdmVhbC52MS5WZWMzEiMKBHRyZWUYBCABKAsyFS5mb3ZlYWwudjEuU3BoZXJlVHJlZRIhCgZjYW1lcmEYBSABKAsyES5mb3ZlYWwudjEuQ2FtZXJhEiIKBHN0YXIYBiABKAsyFC5mb3ZlYWwudjEuU3RhclNoYXBlIksKCVN0YXJTaGFwZRIOCgZyYWRpdXMYASABKAESEwoLY29yZV9yYWRpdXMYAiABKAESGQoRc3Bpa2VfYmFzZV9yYWRpdXMYAyABKAEiawoQQ29uZmlndXJlUmVxdWVzdBImCgZjb25maWcYASABKAsyFi5mb3ZlYWwudjEuU2NlbmVDb25maWcSLwoLdXBkYXRlX21hc2sYAiABKAsyGi5nb29nbGUucHJvdG9idWYuRmllbGRNYXNrIlcKEUNvbmZpZ3VyZVJlc3BvbnNlEicKB2FwcGxpZWQYASABKAsyFi5mb3ZlYWwudjEuU2NlbmVDb25maWcSGQoRZmlyc3RfZnJhbWVfaW5kZXgYAiABKAQiEgoQR2V0U3RhdHVzUmVxdWVzdCLCAgoGU3RhdHVzEhAKCHVwdGltZV9zGAEgASgBEg4KBmZyYW1lcxgCIAEoBBILCgNmcHMYAyABKAESEwoLc3Vic2NyaWJlcnMYBCABKA0SHQoVZ2F6ZV9zYW1wbGVzX2FjY2VwdGVkGAUgASgEEh0KFWdhemVfc2FtcGxlc19yZWplY3RlZBgGIAEoBBIUCgxnYXplX3JhdGVfaHoYByABKAESKgoNbGFzdF9maXhhdGlvbhgIIAEoCzITLmZvdmVhbC52MS5GaXhhdGlvbhImCgZjb25maWcYCSABKAsyFi5mb3ZlYWwudjEuU2NlbmVDb25maWcSIQoZZ2F6ZV9zYW1wbGVzX3JhdGVfbGltaXRlZBgKIAEoBBIZChFnYXplX3NvdXJjZXNfbGl2ZRgLIAEoDRIOCgZwYXVzZWQYDCABKAgiDgoMUGF1c2VSZXF1ZXN0Ig8KDVJlc3VtZVJlcXVlc3QiHQoLU3RlcFJlcXVlc3QSDgoGZnJhbWVzGAEgASgNIisKCUxvb3BTdGF0ZRIOCgZwYXVzZWQYASABKAgSDgoGZnJhbWVzGAIgASgEIiwKDlJlc3RhcnRSZXF1ZXN0EhEKBHNlZWQYASABKARIAIgBAUIHCgVfc2VlZCIiChJJbnNwZWN0Qm9keVJlcXVlc3QSDAoEYm9keRgBIAEoDSKkAQoOUGFpckluc3BlY3Rpb24SDQoFb3RoZXIYASABKA0SJQoGc3RhdHVzGAIgASgOMhUuZm92ZWFsLnYxLlBhaXJTdGF0dXMSDQoFbGV2ZWwYAyABKA0SEwoLb3RoZXJfbGV2ZWwYBCABKA0SFgoOcmVzb2x2ZWRfbGV2ZWwYBSABKA0SEAoIcHJpb3JpdHkYBiABKAESDgoGZm92ZWFsGAcgASgIInIKDkJvZHlJbnNwZWN0aW9uEhMKC2ZyYW1lX2luZGV4GAEgASgEEgwKBGJvZHkYAiABKA0SKAoFcGFpcnMYAyADKAsyGS5mb3ZlYWwudjEuUGFpckluc3BlY3Rpb24SEwoLcGFpcnNfdG90YWwYBCABKA0qSgoDRXllEhMKD0VZRV9VTlNQRUNJRklFRBAAEgwKCEVZRV9MRUZUEAESDQoJRVlFX1JJR0hUEAISEQoNRVlFX0JJTk9DVUxBUhADKr4BCg5GaXhhdGlvblNvdXJjZRIfChtGSVhBVElPTl9TT1VSQ0VfVU5TUEVDSUZJRUQQABIYChRGSVhBVElPTl9TT1VSQ0VfR0FaRRABEiQKIEZJWEFUSU9OX1NPVVJDRV9GQUxMQkFDS19OT19HQVpFEAISIgoeRklYQVRJT05fU09VUkNFX0ZBTExCQUNLX1NUQUxFEAMSJwojRklYQVRJT05fU09VUkNFX0ZBTExCQUNLX1RSQUNLX0xPU1QQBCrJAQoJR2F6ZVRyYWNrEhoKFkdBWkVfVFJBQ0tfVU5TUEVDSUZJRUQQABIWChJHQVpFX1RSQUNLX05PX0dBWkUQARISCg5HQVpFX1RSQUNLX1JBVxACEhcKE0dBWkVfVFJBQ0tfRklYQVRJT04QAxIWChJHQVpFX1RSQUNLX1NBQ0NBREUQBBIWChJHQVpFX1RSQUNLX0hPTERJTkcQBRIWChJHQVpFX1RSQUNLX1dJREVORUQQBhITCg9HQVpFX1RSQUNLX0xPU1QQByrrAQoJU2NoZWR1bGVyEhkKFVNDSEVEVUxFUl9VTlNQRUNJRklFRBAAEhkKFVNDSEVEVUxFUl9ST1VORF9ST0JJThABEhgKFFNDSEVEVUxFUl9TRVFVRU5USUFMEAISHwobU0NIRURVTEVSX1NPUlRFRF9TRVFVRU5USUFMEAMSGwoXU0NIRURVTEVSX1BSSU9SSVRZX09OTFkQBBIdChlTQ0hFRFVMRVJfUFJJT1JJVFlfU09SVEVEEAUSGwoXU0NIRURVTEVSX0VYUEVDVEVEX0dBSU4QBhIUChBTQ0hFRFVMRVJfUFJJQ0VEEAcqcgoQRWNjZW50cmljaXR5VW5pdBIhCh1FQ0NFTlRSSUNJVFlfVU5JVF9VTlNQRUNJRklFRBAAEhwKGEVDQ0VOVFJJQ0lUWV9VTklUX1BJWEVMUxABEh0KGUVDQ0VOVFJJQ0lUWV9VTklUX0RFR1JFRVMQAipOCgRUcmVlEhQKEFRSRUVfVU5TUEVDSUZJRUQQABIOCgpUUkVFX1BBUlRTEAESDwoLVFJFRV9GSVRURUQQAhIPCgtUUkVFX09DVFJFRRADKl8KB0NvbXBhcmUSFwoTQ09NUEFSRV9VTlNQRUNJRklFRBAAEg8KC0NPTVBBUkVfT0ZGEAESFwoTQ09NUEFSRV9ST1VORF9ST0JJThACEhEKDUNPTVBBUkVfRVhBQ1QQAypHCgVUcnV0aBIVChFUUlVUSF9VTlNQRUNJRklFRBAAEg8KC1RSVVRIX1NIQVBFEAESFgoSVFJVVEhfTEVBRl9TUEhFUkVTEAIqqAEKClBhaXJTdGF0dXMSGwoXUEFJUl9TVEFUVVNfVU5TUEVDSUZJRUQQABIYChRQQUlSX1NUQVRVU19VTlRFU1RFRBABEhYKElBBSVJfU1RBVFVTX0FDVElWRRACEhkKFVBBSVJfU1RBVFVTX0NPTExJRElORxADEhgKFFBBSVJfU1RBVFVTX1NFUEFSQVRFEAQSFgoSUEFJUl9TVEFUVVNfREVFTUVEEAUy0wUKBkZvdmVhbBJDCgpTdHJlYW1HYXplEhUuZm92ZWFsLnYxLkdhemVTYW1wbGUaHC5mb3ZlYWwudjEuU3RyZWFtR2F6ZVN1bW1hcnkoARJDCghQdXNoR2F6ZRIaLmZvdmVhbC52MS5QdXNoR2F6ZVJlcXVlc3QaGy5mb3ZlYWwudjEuUHVzaEdhemVSZXNwb25zZRJACgtXYXRjaEZyYW1lcxIdLmZvdmVhbC52MS5XYXRjaEZyYW1lc1JlcXVlc3QaEC5mb3ZlYWwudjEuRnJhbWUwARJDCghHZXRTY2VuZRIaLmZvdmVhbC52MS5HZXRTY2VuZVJlcXVlc3QaGy5mb3ZlYWwudjEuU2NlbmVEZXNjcmlwdGlvbhJGCglDb25maWd1cmUSGy5mb3ZlYWwudjEuQ29uZmlndXJlUmVxdWVzdBocLmZvdmVhbC52MS5Db25maWd1cmVSZXNwb25zZRI7CglHZXRTdGF0dXMSGy5mb3ZlYWwudjEuR2V0U3RhdHVzUmVxdWVzdBoRLmZvdmVhbC52MS5TdGF0dXMSNgoFUGF1c2USFy5mb3ZlYWwudjEuUGF1c2VSZXF1ZXN0GhQuZm92ZWFsLnYxLkxvb3BTdGF0ZRI4CgZSZXN1bWUSGC5mb3ZlYWwudjEuUmVzdW1lUmVxdWVzdBoULmZvdmVhbC52MS5Mb29wU3RhdGUSNAoEU3RlcBIWLmZvdmVhbC52MS5TdGVwUmVxdWVzdBoULmZvdmVhbC52MS5Mb29wU3RhdGUSQgoHUmVzdGFydBIZLmZvdmVhbC52MS5SZXN0YXJ0UmVxdWVzdBocLmZvdmVhbC52MS5Db25maWd1cmVSZXNwb25zZRJHCgtJbnNwZWN0Qm9keRIdLmZvdmVhbC52MS5JbnNwZWN0Qm9keVJlcXVlc3QaGS5mb3ZlYWwudjEuQm9keUluc3BlY3Rpb25iBnByb3RvMw",[Y0]),L_=vn(fr,0);var Ed=vn(fr,15);var D_=vn(fr,17),po=vn(fr,18),F_=vn(fr,19),U_=vn(fr,20),O_=vn(fr,21),B_=vn(fr,22),k_=vn(fr,23);var V_=w_(fr,0);var As=class{constructor(e=500,t=5e3,i=Math.random){this.baseMs=e;this.capMs=t;this.random=i;this.nominal=e}baseMs;capMs;random;nominal;until=0;fail(e=performance.now()){let t=this.nominal*(.5+.5*this.random());return this.nominal=Math.min(this.capMs,2*this.nominal),this.until=e+t,t}succeed(){this.nominal=this.baseMs,this.until=0}ready(e=performance.now()){return e>=this.until}};var Mc=[["priced",7],["round-robin",1],["sequential",2],["sorted-sequential",3],["priority-only",4],["priority-sorted",5],["expected-gain",6]];function wc(n){return Mc.find(([,e])=>e===n)?.[0]??"unknown"}var Fa=[["shape",1,"colliding: the drawn stars touch"],["leaf-spheres",2,"colliding: leaf spheres overlap (the paper's definition)"]];function Tc(n){return Fa.find(([,e])=>e===n)?.[0]??"unknown"}function z_(n){return Fa.find(([,e])=>e===n)?.[2]??"the server did not say what colliding means"}function H_(n){let e=n.trim().toLowerCase(),t=i=>{let r=Number(i);if(i===""||!Number.isFinite(r))throw new Error(`budget "${n}": "${i}" is not a number`);return r};if(e==="exact")return xt(po,{kind:{case:"exact",value:xt(D_)}});if(e==="zero")return xt(po,{kind:{case:"interruptAtZero",value:!0}});if(e.endsWith("ms"))return xt(po,{kind:{case:"wallMs",value:t(e.slice(0,-2))}});if(e.endsWith("tests")){let i=t(e.slice(0,-5));if(!Number.isInteger(i)||i<0)throw new Error(`budget "${n}": sphere tests must be a whole number`);return xt(po,{kind:{case:"sphereTests",value:BigInt(i)}})}if(e.endsWith("x"))return xt(po,{kind:{case:"fractionOfExact",value:t(e.slice(0,-1))}});throw new Error(`budget "${n}": use exact, zero, 4ms, 20000tests or 0.3x`)}function Md(n){switch(n?.kind.case){case"exact":return"exact";case"interruptAtZero":return"zero";case"wallMs":return`${n.kind.value}ms`;case"sphereTests":return`${n.kind.value}tests`;case"fractionOfExact":return`${n.kind.value}x`;default:return""}}var G_={deg:2,px:1};function wd(n){let e=n.trim().toLowerCase().split(":"),t=2,i=e[e.length-1];e.length>1&&i in G_&&(t=G_[i],e.pop());let r=(o,a)=>{let l=(o??"").split(",").map(Number);if(l.length!==a||l.some(c=>!Number.isFinite(c)))throw new Error(`model "${n}": expected ${a} number${a>1?"s":""} after "${e[0]}:"`);return l},s=o=>xt(k_,{model:o,eccentricityUnit:t});switch(e[0]){case"f1":return s({case:"f1",value:xt(F_)});case"f2":{let[o]=r(e[1],1);return s({case:"f2",value:xt(U_,{c:o})})}case"f2range":{let[o,a]=r(e[1],2);return s({case:"f2Range",value:xt(O_,{cMin:o,cMax:a})})}case"f3":{let[o,a,l,c,u]=r(e[1],5);return s({case:"f3",value:xt(B_,{c1:o,c2:a,c3:l,e1:c,e2:u})})}default:throw new Error(`model "${n}": use f1, f2:<C>, f2range:<Cmin>,<Cmax> or f3:<c1>,<c2>,<c3>,<e1>,<e2>, optionally :deg or :px`)}}function Td(n){if(!n)return"";let e=n.eccentricityUnit===1?"px":"deg";switch(n.model.case){case"f1":return`f1:${e}`;case"f2":return`f2:${n.model.value.c}:${e}`;case"f2Range":return`f2range:${n.model.value.cMin},${n.model.value.cMax}:${e}`;case"f3":{let t=n.model.value;return`f3:${t.c1},${t.c2},${t.c3},${t.e1},${t.e2}:${e}`}default:return""}}var YM=8,ZM=100,W_=256,Ac=class{constructor(e,t){this.client=e;this.target=t;t.addEventListener("pointermove",i=>this.move(i)),t.addEventListener("pointerleave",()=>this.held=!0),setInterval(()=>this.tick(),YM)}client;target;enabled=!0;pointer=null;held=!1;accepted=0;lastError="";lastRoundTripMs=0;lastPointerAt=0;pending=[];inFlight=0;lastSent=0;backoff=new As;move(e){let t=this.target.getBoundingClientRect();t.width<=0||t.height<=0||(this.pointer={x:(e.clientX-t.left)/t.width,y:(e.clientY-t.top)/t.height},this.held=!1,this.lastPointerAt=performance.now(),this.sample())}sample(){!this.enabled||!this.pointer||document.hidden||(this.pending.push(xt(L_,{trackerTimeS:performance.now()/1e3,x:this.pointer.x,y:this.pointer.y,validity:1})),this.pending.length>W_&&this.pending.splice(0,this.pending.length-W_),this.flush())}tick(){this.enabled&&this.pointer&&this.inFlight===0&&this.pending.length===0&&performance.now()-this.lastSent>ZM?this.sample():this.flush()}async flush(){if(this.inFlight>=2||this.pending.length===0||!this.backoff.ready())return;let e=this.pending;this.pending=[],this.inFlight++,this.lastSent=performance.now();try{let t=performance.now(),i=await this.client.pushGaze({samples:e,source:"viewer:mouse"});this.lastRoundTripMs=performance.now()-t,this.accepted+=Number(i.accepted),this.lastError=i.rejections[0]?`${i.rejections[0].field}: ${i.rejections[0].reason}`:"",this.backoff.succeed()}catch(t){this.lastError=t instanceof Error?t.message:String(t),this.backoff.fail()}finally{this.inFlight--}}};function Y_(n,e){let t=n.widthPx,i=n.heightPx,r=n.diagonalIn*2.54/Math.hypot(t,i),s=n.viewingDistanceCm*Math.tan(e*Math.PI/180)/r;return{rx:s/t,ry:s/i}}var Ua=class{constructor(e){this.canvas=e;let t=e.getContext("2d");if(!t)throw new Error("no 2D canvas context");this.ctx=t}canvas;ctx;resize(e,t){this.canvas.width=e,this.canvas.height=t}label(e,t=[]){let{ctx:i,canvas:r}=this;i.clearRect(0,0,r.width,r.height),i.font="15px system-ui, sans-serif",i.textBaseline="top";let s=Math.max(...e.map(l=>i.measureText(l).width));i.fillStyle="rgba(16,20,24,0.75)",i.fillRect(6,6,s+16,22*e.length+8),i.fillStyle="rgba(255,214,10,0.95)",e.forEach((l,c)=>i.fillText(l,14,12+22*c)),i.strokeStyle="rgba(255,214,10,0.95)",i.lineWidth=2,i.beginPath();let o=r.width,a=r.height;t.length===1&&i.arc(t[0].x*o,t[0].y*a,12,0,2*Math.PI),t.forEach((l,c)=>c?i.lineTo(l.x*o,l.y*a):i.moveTo(l.x*o,l.y*a)),i.stroke()}draw(e,t,i){let{ctx:r,canvas:s}=this,o=s.width,a=s.height;if(r.clearRect(0,0,o,a),e){let l=e.x*o,c=e.y*a,u=e.source!==1;r.strokeStyle=u?"rgba(255,255,255,0.45)":"rgba(255,214,10,0.95)",r.lineWidth=2,t&&(r.setLineDash(u?[6,6]:[]),r.beginPath(),r.ellipse(l,c,t.rx*o,t.ry*a,0,0,2*Math.PI),r.stroke(),r.setLineDash([])),r.beginPath(),r.moveTo(l-10,c),r.lineTo(l+10,c),r.moveTo(l,c-10),r.lineTo(l,c+10),r.stroke()}i&&(r.fillStyle="rgba(120,200,255,0.9)",r.beginPath(),r.arc(i.x*o,i.y*a,3,0,2*Math.PI),r.fill())}};var KM="uplot",$M="u-hz",qM="u-vt",JM="u-title",jM="u-wrap",QM="u-under",ew="u-over",tw="u-axis",Cs="u-off",nw="u-select",iw="u-cursor-x",rw="u-cursor-y",sw="u-cursor-pt",ow="u-legend",aw="u-live",lw="u-inline",cw="u-series",uw="u-marker",Z_="u-label",hw="u-value",Ba="width",ka="height";var K_="bottom",mo="left",Ad="right",Wd="#000",$_=Wd+"0",Rd="mousemove",q_="mousedown",Id="mouseup",J_="mouseenter",j_="mouseleave",Q_="dblclick",fw="resize",dw="scroll",ey="change",Pc="dppxchange",Xd="--",So=typeof window<"u",Dd=So?document:null,_o=So?window:null,pw=So?navigator:null,Ct,Rc;function Fd(){let n=devicePixelRatio;Ct!=n&&(Ct=n,Rc&&Od(ey,Rc,Fd),Rc=matchMedia(`(min-resolution: ${Ct-.001}dppx) and (max-resolution: ${Ct+.001}dppx)`),Ns(ey,Rc,Fd),_o.dispatchEvent(new CustomEvent(Pc)))}function _i(n,e){if(e!=null){let t=n.classList;!t.contains(e)&&t.add(e)}}function Ud(n,e){let t=n.classList;t.contains(e)&&t.remove(e)}function qt(n,e,t){n.style[e]=t+"px"}function Wi(n,e,t,i){let r=Dd.createElement(n);return e!=null&&_i(r,e),t?.insertBefore(r,i),r}function Ni(n,e){return Wi("div",n,e)}var ty=new WeakMap;function dr(n,e,t,i,r){let s="translate("+e+"px,"+t+"px)",o=ty.get(n);s!=o&&(n.style.transform=s,ty.set(n,s),e<0||t<0||e>i||t>r?_i(n,Cs):Ud(n,Cs))}var ny=new WeakMap;function iy(n,e,t){let i=e+t,r=ny.get(n);i!=r&&(ny.set(n,i),n.style.background=e,n.style.borderColor=t)}var ry=new WeakMap;function sy(n,e,t,i){let r=e+""+t,s=ry.get(n);r!=s&&(ry.set(n,r),n.style.height=t+"px",n.style.width=e+"px",n.style.marginLeft=i?-e/2+"px":0,n.style.marginTop=i?-t/2+"px":0)}var Yd={passive:!0},mw={...Yd,capture:!0};function Ns(n,e,t,i){e.addEventListener(n,t,i?mw:Yd)}function Od(n,e,t,i){e.removeEventListener(n,t,Yd)}So&&Fd();function Xi(n,e,t,i){let r;t=t||0,i=i||e.length-1;let s=i<=2147483647;for(;i-t>1;)r=s?t+i>>1:yi((t+i)/2),e[r]<n?t=r:i=r;return n-e[t]<=e[i]-n?t:i}function Ly(n){return(t,i,r)=>{let s=-1,o=-1;for(let a=i;a<=r;a++)if(n(t[a])){s=a;break}for(let a=r;a>=i;a--)if(n(t[a])){o=a;break}return[s,o]}}var Dy=n=>n!=null,Fy=n=>n!=null&&n>0,Fc=Ly(Dy),gw=Ly(Fy);function _w(n,e,t,i=0,r=!1){let s=r?gw:Fc,o=r?Fy:Dy;[e,t]=s(n,e,t);let a=n[e],l=n[e];if(e>-1)if(i==1)a=n[e],l=n[t];else if(i==-1)a=n[t],l=n[e];else for(let c=e;c<=t;c++){let u=n[c];o(u)&&(u<a?a=u:u>l&&(l=u))}return[a??zt,l??-zt]}function Uc(n,e,t,i){let r=ly(n),s=ly(e);n==e&&(r==-1?(n*=t,e/=t):(n/=t,e*=t));let o=t==10?Cr:Uy,a=r==1?yi:Pi,l=s==1?Pi:yi,c=a(o(Rn(n))),u=l(o(Rn(e))),h=yo(t,c),f=yo(t,u);return t==10&&(c<0&&(h=Ht(h,-c)),u<0&&(f=Ht(f,-u))),i||t==2?(n=h*r,e=f*s):(n=Vy(n,h),e=Oc(e,f)),[n,e]}function Zd(n,e,t,i){let r=Uc(n,e,t,i);return n==0&&(r[0]=0),e==0&&(r[1]=0),r}var Kd=.1,oy={mode:3,pad:Kd},Ga={pad:0,soft:null,mode:0},yw={min:Ga,max:Ga};function Lc(n,e,t,i){return Bc(t)?ay(n,e,t):(Ga.pad=t,Ga.soft=i?0:null,Ga.mode=i?3:0,ay(n,e,yw))}function Rt(n,e){return n??e}function xw(n,e,t){for(e=Rt(e,0),t=Rt(t,n.length-1);e<=t;){if(n[e]!=null)return!0;e++}return!1}function ay(n,e,t){let i=t.min,r=t.max,s=Rt(i.pad,0),o=Rt(r.pad,0),a=Rt(i.hard,-zt),l=Rt(r.hard,zt),c=Rt(i.soft,zt),u=Rt(r.soft,-zt),h=Rt(i.mode,0),f=Rt(r.mode,0),d=e-n,p=Cr(d),x=ni(Rn(n),Rn(e)),m=Cr(x),g=Rn(m-p);(d<1e-24||g>10)&&(d=0,(n==0||e==0)&&(d=1e-24,h==2&&c!=zt&&(s=0),f==2&&u!=-zt&&(o=0)));let b=d||x||1e3,T=Cr(b),v=yo(10,yi(T)),R=b*(d==0?n==0?.1:1:s),A=Ht(Vy(n-R,v/10),24),_=n>=c&&(h==1||h==3&&A<=c||h==2&&A>=c)?c:zt,E=ni(a,A<_&&n>=_?_:Yi(_,A)),F=b*(d==0?e==0?.1:1:o),N=Ht(Oc(e+F,v/10),24),P=e<=u&&(f==1||f==3&&N>=u||f==2&&N<=u)?u:-zt,k=Yi(l,N>P&&e<=P?P:ni(P,N));return E==k&&E==0&&(k=100),[E,k]}var bw=new Intl.NumberFormat(So?pw.language:"en-US"),$d=n=>bw.format(n),xi=Math,Nc=xi.PI,Rn=xi.abs,yi=xi.floor,An=xi.round,Pi=xi.ceil,Yi=xi.min,ni=xi.max,yo=xi.pow,ly=xi.sign,Cr=xi.log10,Uy=xi.log2,vw=(n,e=1)=>xi.sinh(n)*e,Cd=(n,e=1)=>xi.asinh(n/e),zt=1/0;function cy(n){return(Cr((n^n>>31)-(n>>31))|0)+1}function Bd(n,e,t){return Yi(ni(n,e),t)}function Oy(n){return typeof n=="function"}function vt(n){return Oy(n)?n:()=>n}var Sw=()=>{},By=n=>n,ky=(n,e)=>e,Ew=n=>null,uy=n=>!0,hy=(n,e)=>n==e,Mw=/\.\d*?(?=9{6,}|0{6,})/gm,Ps=n=>{if(zy(n)||is.has(n))return n;let e=`${n}`,t=e.match(Mw);if(t==null)return n;let i=t[0].length-1;if(e.indexOf("e-")!=-1){let[r,s]=e.split("e");return+`${Ps(r)}e${s}`}return Ht(n,i)};function Rs(n,e){return Ps(Ht(Ps(n/e))*e)}function Oc(n,e){return Ps(Pi(Ps(n/e))*e)}function Vy(n,e){return Ps(yi(Ps(n/e))*e)}function Ht(n,e=0){if(zy(n))return n;let t=10**e,i=n*t*(1+Number.EPSILON);return An(i)/t}var is=new Map;function Gy(n){return((""+n).split(".")[1]||"").length}function Ha(n,e,t,i){let r=[],s=i.map(Gy);for(let o=e;o<t;o++){let a=Rn(o),l=Ht(yo(n,o),a);for(let c=0;c<i.length;c++){let u=n==10?+`${i[c]}e${o}`:i[c]*l,h=(o>=0?0:a)+(o>=s[c]?0:s[c]),f=n==10?u:Ht(u,h);r.push(f),is.set(f,h)}}return r}var za={},qd=[],xo=[null,null],ns=Array.isArray,zy=Number.isInteger,ww=n=>n===void 0;function fy(n){return typeof n=="string"}function Bc(n){let e=!1;if(n!=null){let t=n.constructor;e=t==null||t==Object}return e}function Tw(n){return n!=null&&typeof n=="object"}var Aw=Object.getPrototypeOf(Uint8Array),Hy="__proto__";function bo(n,e=Bc){let t;if(ns(n)){let i=n.find(r=>r!=null);if(ns(i)||e(i)){t=Array(n.length);for(let r=0;r<n.length;r++)t[r]=bo(n[r],e)}else t=n.slice()}else if(n instanceof Aw)t=n.slice();else if(e(n)){t={};for(let i in n)i!=Hy&&(t[i]=bo(n[i],e))}else t=n;return t}function Sn(n){let e=arguments;for(let t=1;t<e.length;t++){let i=e[t];for(let r in i)r!=Hy&&(Bc(n[r])?Sn(n[r],bo(i[r])):n[r]=bo(i[r]))}return n}var Rw=0,Iw=1,Cw=2;function Nw(n,e,t){for(let i=0,r,s=-1;i<e.length;i++){let o=e[i];if(o>s){for(r=o-1;r>=0&&n[r]==null;)n[r--]=null;for(r=o+1;r<t&&n[r]==null;)n[s=r++]=null}}}function Pw(n,e){if(Fw(n)){let o=n[0].slice();for(let a=1;a<n.length;a++)o.push(...n[a].slice(1));return Uw(o[0])||(o=Dw(o)),o}let t=new Set;for(let o=0;o<n.length;o++){let l=n[o][0],c=l.length;for(let u=0;u<c;u++)t.add(l[u])}let i=[Array.from(t).sort((o,a)=>o-a)],r=i[0].length,s=new Map;for(let o=0;o<r;o++)s.set(i[0][o],o);for(let o=0;o<n.length;o++){let a=n[o],l=a[0];for(let c=1;c<a.length;c++){let u=a[c],h=Array(r).fill(void 0),f=e?e[o][c]:Iw,d=[];for(let p=0;p<u.length;p++){let x=u[p],m=s.get(l[p]);x===null?f!=Rw&&(h[m]=x,f==Cw&&d.push(m)):h[m]=x}Nw(h,d,r),i.push(h)}}return i}var Lw=typeof queueMicrotask>"u"?n=>Promise.resolve().then(n):queueMicrotask;function Dw(n){let e=n[0],t=e.length,i=Array(t);for(let s=0;s<i.length;s++)i[s]=s;i.sort((s,o)=>e[s]-e[o]);let r=[];for(let s=0;s<n.length;s++){let o=n[s],a=Array(t);for(let l=0;l<t;l++)a[l]=o[i[l]];r.push(a)}return r}function Fw(n){let e=n[0][0],t=e.length;for(let i=1;i<n.length;i++){let r=n[i][0];if(r.length!=t)return!1;if(r!=e){for(let s=0;s<t;s++)if(r[s]!=e[s])return!1}}return!0}function Uw(n,e=100){let t=n.length;if(t<=1)return!0;let i=0,r=t-1;for(;i<=r&&n[i]==null;)i++;for(;r>=i&&n[r]==null;)r--;if(r<=i)return!0;let s=ni(1,yi((r-i+1)/e));for(let o=n[i],a=i+s;a<=r;a+=s){let l=n[a];if(l!=null){if(l<=o)return!1;o=l}}return!0}var Wy=["January","February","March","April","May","June","July","August","September","October","November","December"],Xy=["Sunday","Monday","Tuesday","Wednesday","Thursday","Friday","Saturday"];function Yy(n){return n.slice(0,3)}var Ow=Xy.map(Yy),Bw=Wy.map(Yy),kw={MMMM:Wy,MMM:Bw,WWWW:Xy,WWW:Ow};function Oa(n){return(n<10?"0":"")+n}function Vw(n){return(n<10?"00":n<100?"0":"")+n}var Gw={YYYY:n=>n.getFullYear(),YY:n=>(n.getFullYear()+"").slice(2),MMMM:(n,e)=>e.MMMM[n.getMonth()],MMM:(n,e)=>e.MMM[n.getMonth()],MM:n=>Oa(n.getMonth()+1),M:n=>n.getMonth()+1,DD:n=>Oa(n.getDate()),D:n=>n.getDate(),WWWW:(n,e)=>e.WWWW[n.getDay()],WWW:(n,e)=>e.WWW[n.getDay()],HH:n=>Oa(n.getHours()),H:n=>n.getHours(),h:n=>{let e=n.getHours();return e==0?12:e>12?e-12:e},AA:n=>n.getHours()>=12?"PM":"AM",aa:n=>n.getHours()>=12?"pm":"am",a:n=>n.getHours()>=12?"p":"a",mm:n=>Oa(n.getMinutes()),m:n=>n.getMinutes(),ss:n=>Oa(n.getSeconds()),s:n=>n.getSeconds(),fff:n=>Vw(n.getMilliseconds())};function Jd(n,e){e=e||kw;let t=[],i=/\{([a-z]+)\}|[^{]+/gi,r;for(;r=i.exec(n);)t.push(r[0][0]=="{"?Gw[r[1]]:r[0]);return s=>{let o="";for(let a=0;a<t.length;a++)o+=typeof t[a]=="string"?t[a]:t[a](s,e);return o}}var zw=new Intl.DateTimeFormat().resolvedOptions().timeZone;function Hw(n,e){let t;return e=="UTC"||e=="Etc/UTC"?t=new Date(+n+n.getTimezoneOffset()*6e4):e==zw?t=n:(t=new Date(n.toLocaleString("en-US",{timeZone:e})),t.setMilliseconds(n.getMilliseconds())),t}var Zy=n=>n%1==0,Dc=[1,2,2.5,5],Ww=Ha(10,-32,0,Dc),Ky=Ha(10,0,32,Dc),Xw=Ky.filter(Zy),Is=Ww.concat(Ky),jd=`
`,$y="{YYYY}",dy=jd+$y,qy="{M}/{D}",Va=jd+qy,Ic=Va+"/{YY}",Jy="{aa}",Yw="{h}:{mm}",go=Yw+Jy,py=jd+go,my=":{ss}",Pt=null;function jy(n){let e=n*1e3,t=e*60,i=t*60,r=i*24,s=r*30,o=r*365,l=(n==1?Ha(10,0,3,Dc).filter(Zy):Ha(10,-3,0,Dc)).concat([e,e*5,e*10,e*15,e*30,t,t*5,t*10,t*15,t*30,i,i*2,i*3,i*4,i*6,i*8,i*12,r,r*2,r*3,r*4,r*5,r*6,r*7,r*8,r*9,r*10,r*15,s,s*2,s*3,s*4,s*6,o,o*2,o*5,o*10,o*25,o*50,o*100]),c=[[o,$y,Pt,Pt,Pt,Pt,Pt,Pt,1],[r*28,"{MMM}",dy,Pt,Pt,Pt,Pt,Pt,1],[r,qy,dy,Pt,Pt,Pt,Pt,Pt,1],[i,"{h}"+Jy,Ic,Pt,Va,Pt,Pt,Pt,1],[t,go,Ic,Pt,Va,Pt,Pt,Pt,1],[e,my,Ic+" "+go,Pt,Va+" "+go,Pt,py,Pt,1],[n,my+".{fff}",Ic+" "+go,Pt,Va+" "+go,Pt,py,Pt,1]];function u(h){return(f,d,p,x,m,g)=>{let b=[],T=m>=o,v=m>=s&&m<o,R=h(p),A=Ht(R*n,3),_=Nd(R.getFullYear(),T?0:R.getMonth(),v||T?1:R.getDate()),E=Ht(_*n,3);if(v||T){let F=v?m/s:0,N=T?m/o:0,P=A==E?A:Ht(Nd(_.getFullYear()+N,_.getMonth()+F,1)*n,3),k=new Date(An(P/n)),H=k.getFullYear(),D=k.getMonth();for(let W=0;P<=x;W++){let K=Nd(H+N*W,D+F*W,1),z=K-h(Ht(K*n,3));P=Ht((+K+z)*n,3),P<=x&&b.push(P)}}else{let F=m>=r?r:m,N=yi(p)-yi(A),P=E+N+Oc(A-E,F);b.push(P);let k=h(P),H=k.getHours()+k.getMinutes()/t+k.getSeconds()/i,D=m/i,W=f.axes[d]._space,K=g/W;for(;P=Ht(P+m,n==1?0:3),!(P>x);)if(D>1){let z=yi(Ht(H+D,6))%24,Q=h(P).getHours()-z;Q>1&&(Q=-1),P-=Q*i,H=(H+D)%24;let re=b[b.length-1];Ht((P-re)/m,3)*K>=.7&&b.push(P)}else b.push(P)}return b}}return[l,c,u]}var[Zw,Kw,$w]=jy(1),[qw,Jw,jw]=jy(.001);Ha(2,-53,53,[1]);function gy(n,e){return n.map(t=>t.map((i,r)=>r==0||r==8||i==null?i:e(r==1||t[8]==0?i:t[1]+i)))}function _y(n,e){return(t,i,r,s,o)=>{let a=e.find(p=>o>=p[0])||e[e.length-1],l,c,u,h,f,d;return i.map(p=>{let x=n(p),m=x.getFullYear(),g=x.getMonth(),b=x.getDate(),T=x.getHours(),v=x.getMinutes(),R=x.getSeconds(),A=m!=l&&a[2]||g!=c&&a[3]||b!=u&&a[4]||T!=h&&a[5]||v!=f&&a[6]||R!=d&&a[7]||a[1];return l=m,c=g,u=b,h=T,f=v,d=R,A(x)})}}function Qw(n,e){let t=Jd(e);return(i,r,s,o,a)=>r.map(l=>t(n(l)))}function Nd(n,e,t){return new Date(n,e,t)}function yy(n,e){return e(n)}var eT="{YYYY}-{MM}-{DD} {h}:{mm}{aa}";function xy(n,e){return(t,i,r,s)=>s==null?Xd:e(n(i))}function tT(n,e){let t=n.series[e];return t.width?t.stroke(n,e):t.points.width?t.points.stroke(n,e):null}function nT(n,e){return n.series[e].fill(n,e)}var iT={show:!0,live:!0,isolate:!1,mount:Sw,markers:{show:!0,width:2,stroke:tT,fill:nT,dash:"solid"},idx:null,idxs:null,values:[]};function rT(n,e){let t=n.cursor.points,i=Ni(),r=t.size(n,e);qt(i,Ba,r),qt(i,ka,r);let s=r/-2;qt(i,"marginLeft",s),qt(i,"marginTop",s);let o=t.width(n,e,r);return o&&qt(i,"borderWidth",o),i}function sT(n,e){let t=n.series[e].points;return t._fill||t._stroke}function oT(n,e){let t=n.series[e].points;return t._stroke||t._fill}function aT(n,e){return n.series[e].points.size}var Pd=[0,0];function lT(n,e,t){return Pd[0]=e,Pd[1]=t,Pd}function Cc(n,e,t,i=!0){return r=>{r.button==0&&(!i||r.target==e)&&t(r)}}function Ld(n,e,t,i=!0){return r=>{(!i||r.target==e)&&t(r)}}var cT={show:!0,x:!0,y:!0,lock:!1,move:lT,points:{one:!1,show:rT,size:aT,width:0,stroke:oT,fill:sT},bind:{mousedown:Cc,mouseup:Cc,click:Cc,dblclick:Cc,mousemove:Ld,mouseleave:Ld,mouseenter:Ld},drag:{setScale:!0,x:!0,y:!1,dist:0,uni:null,click:(n,e)=>{e.stopPropagation(),e.stopImmediatePropagation()},_x:!1,_y:!1},focus:{dist:(n,e,t,i,r)=>i-r,prox:-1,bias:0},hover:{skip:[void 0],prox:null,bias:0},left:-10,top:-10,idx:null,dataIdx:null,idxs:null,event:null},Qy={show:!0,stroke:"rgba(0,0,0,0.07)",width:2},Qd=Sn({},Qy,{filter:ky}),ex=Sn({},Qd,{size:10}),tx=Sn({},Qy,{show:!1}),ep='12px system-ui, -apple-system, "Segoe UI", Roboto, "Helvetica Neue", Arial, "Noto Sans", sans-serif, "Apple Color Emoji", "Segoe UI Emoji", "Segoe UI Symbol", "Noto Color Emoji"',nx="bold "+ep,ix=1.5,by={show:!0,scale:"x",stroke:Wd,space:50,gap:5,alignTo:1,size:50,labelGap:0,labelSize:30,labelFont:nx,side:2,grid:Qd,ticks:ex,border:tx,font:ep,lineGap:ix,rotate:0},uT="Value",hT="Time",vy={show:!0,scale:"x",auto:!1,sorted:1,min:zt,max:-zt,idxs:[]};function fT(n,e,t,i,r){return e.map(s=>s==null?"":$d(s))}function dT(n,e,t,i,r,s,o){let a=[],l=is.get(r)||0;t=o?t:Ht(Oc(t,r),l);for(let c=t;c<=i;c=Ht(c+r,l))a.push(Object.is(c,-0)?0:c);return a}function kd(n,e,t,i,r,s,o){let a=[],l=n.scales[n.axes[e].scale].log,c=l==10?Cr:Uy,u=yi(c(t));r=yo(l,u),l==10&&(r=Is[Xi(r,Is)]);let h=t,f=r*l;l==10&&(f=Is[Xi(f,Is)]);do a.push(h),h=h+r,l==10&&!is.has(h)&&(h=Ht(h,is.get(r))),h>=f&&(r=h,f=r*l,l==10&&(f=Is[Xi(f,Is)]));while(h<=i);return a}function pT(n,e,t,i,r,s,o){let l=n.scales[n.axes[e].scale].asinh,c=i>l?kd(n,e,ni(l,t),i,r):[l],u=i>=0&&t<=0?[0]:[];return(t<-l?kd(n,e,ni(l,-i),-t,r):[l]).reverse().map(f=>-f).concat(u,c)}var rx=/./,mT=/[12357]/,gT=/[125]/,Sy=/1/,Vd=(n,e,t,i)=>n.map((r,s)=>e==4&&r==0||s%i==0&&t.test(r.toExponential()[r<0?1:0])?r:null);function _T(n,e,t,i,r){let s=n.axes[t],o=s.scale,a=n.scales[o],l=n.valToPos,c=s._space,u=l(10,o),h=l(9,o)-u>=c?rx:l(7,o)-u>=c?mT:l(5,o)-u>=c?gT:Sy;if(h==Sy){let f=Rn(l(1,o)-u);if(f<c)return Vd(e.slice().reverse(),a.distr,h,Pi(c/f)).reverse()}return Vd(e,a.distr,h,1)}function yT(n,e,t,i,r){let s=n.axes[t],o=s.scale,a=s._space,l=n.valToPos,c=Rn(l(1,o)-l(2,o));return c<a?Vd(e.slice().reverse(),3,rx,Pi(a/c)).reverse():e}function xT(n,e,t,i){return i==null?Xd:e==null?"":$d(e)}var Ey={show:!0,scale:"y",stroke:Wd,space:30,gap:5,alignTo:1,size:50,labelGap:0,labelSize:30,labelFont:nx,side:3,grid:Qd,ticks:ex,border:tx,font:ep,lineGap:ix,rotate:0};function bT(n,e){let t=3+(n||1)*2;return Ht(t*e,3)}function vT(n,e){let{scale:t,idxs:i}=n.series[0],r=n._data[0],s=n.valToPos(r[i[0]],t,!0),o=n.valToPos(r[i[1]],t,!0),a=Rn(o-s),l=n.series[e],c=a/(l.points.space*Ct);return i[1]-i[0]<=c}var My={scale:null,auto:!0,sorted:0,min:zt,max:-zt},sx=(n,e,t,i,r)=>r,wy={show:!0,auto:!0,sorted:0,gaps:sx,alpha:1,facets:[Sn({},My,{scale:"x"}),Sn({},My,{scale:"y"})]},Ty={scale:"y",auto:!0,sorted:0,show:!0,spanGaps:!1,gaps:sx,alpha:1,points:{show:vT,filter:null},values:null,min:zt,max:-zt,idxs:[],path:null,clip:null};function ST(n,e,t,i,r){return t/10}var ox={time:!0,auto:!0,distr:1,log:10,asinh:1,min:null,max:null,dir:1,ori:0},ET=Sn({},ox,{time:!1,ori:1}),Ay={};function ax(n,e){let t=Ay[n];return t||(t={key:n,plots:[],sub(i){t.plots.push(i)},unsub(i){t.plots=t.plots.filter(r=>r!=i)},pub(i,r,s,o,a,l,c){for(let u=0;u<t.plots.length;u++)t.plots[u]!=r&&t.plots[u].pub(i,r,s,o,a,l,c)}},n!=null&&(Ay[n]=t)),t}var vo=1,Gd=2;function Ls(n,e,t){let i=n.mode,r=n.series[e],s=i==2?n._data[e]:n._data,o=n.scales,a=n.bbox,l=s[0],c=i==2?s[1]:s[e],u=i==2?o[r.facets[0].scale]:o[n.series[0].scale],h=i==2?o[r.facets[1].scale]:o[r.scale],f=a.left,d=a.top,p=a.width,x=a.height,m=n.valToPosH,g=n.valToPosV;return u.ori==0?t(r,l,c,u,h,m,g,f,d,p,x,Vc,Eo,zc,cx,hx):t(r,l,c,u,h,g,m,d,f,x,p,Gc,Mo,ip,ux,fx)}function tp(n,e){let t=0,i=0,r=Rt(n.bands,qd);for(let s=0;s<r.length;s++){let o=r[s];o.series[0]==e?t=o.dir:o.series[1]==e&&(o.dir==1?i|=1:i|=2)}return[t,i==1?-1:i==2?1:i==3?2:0]}function MT(n,e,t,i,r){let s=n.mode,o=n.series[e],a=s==2?o.facets[1].scale:o.scale,l=n.scales[a];return r==-1?l.min:r==1?l.max:l.distr==3?l.dir==1?l.min:l.max:0}function Nr(n,e,t,i,r,s){return Ls(n,e,(o,a,l,c,u,h,f,d,p,x,m)=>{let g=o.pxRound,b=c.dir*(c.ori==0?1:-1),T=c.ori==0?Eo:Mo,v,R;b==1?(v=t,R=i):(v=i,R=t);let A=g(h(a[v],c,x,d)),_=g(f(l[v],u,m,p)),E=g(h(a[R],c,x,d)),F=g(f(s==1?u.max:u.min,u,m,p)),N=new Path2D(r);return T(N,E,F),T(N,A,F),T(N,A,_),N})}function kc(n,e,t,i,r,s){let o=null;if(n.length>0){o=new Path2D;let a=e==0?zc:ip,l=t;for(let h=0;h<n.length;h++){let f=n[h];if(f[1]>f[0]){let d=f[0]-l;d>0&&a(o,l,i,d,i+s),l=f[1]}}let c=t+r-l,u=10;c>0&&a(o,l,i-u/2,c,i+s+u)}return o}function wT(n,e,t){let i=n[n.length-1];i&&i[0]==e?i[1]=t:n.push([e,t])}function np(n,e,t,i,r,s,o){let a=[],l=n.length;for(let c=r==1?t:i;c>=t&&c<=i;c+=r)if(e[c]===null){let h=c,f=c;if(r==1)for(;++c<=i&&e[c]===null;)f=c;else for(;--c>=t&&e[c]===null;)f=c;let d=s(n[h]),p=f==h?d:s(n[f]),x=h-r;d=o<=0&&x>=0&&x<l?s(n[x]):d;let g=f+r;p=o>=0&&g>=0&&g<l?s(n[g]):p,p>=d&&a.push([d,p])}return a}function Ry(n){return n==0?By:n==1?An:e=>Rs(e,n)}function lx(n){let e=n==0?Vc:Gc,t=n==0?(r,s,o,a,l,c)=>{r.arcTo(s,o,a,l,c)}:(r,s,o,a,l,c)=>{r.arcTo(o,s,l,a,c)},i=n==0?(r,s,o,a,l)=>{r.rect(s,o,a,l)}:(r,s,o,a,l)=>{r.rect(o,s,l,a)};return(r,s,o,a,l,c=0,u=0)=>{c==0&&u==0?i(r,s,o,a,l):(c=Yi(c,a/2,l/2),u=Yi(u,a/2,l/2),e(r,s+c,o),t(r,s+a,o,s+a,o+l,c),t(r,s+a,o+l,s,o+l,u),t(r,s,o+l,s,o,u),t(r,s,o,s+a,o,c),r.closePath())}}var Vc=(n,e,t)=>{n.moveTo(e,t)},Gc=(n,e,t)=>{n.moveTo(t,e)},Eo=(n,e,t)=>{n.lineTo(e,t)},Mo=(n,e,t)=>{n.lineTo(t,e)},zc=lx(0),ip=lx(1),cx=(n,e,t,i,r,s)=>{n.arc(e,t,i,r,s)},ux=(n,e,t,i,r,s)=>{n.arc(t,e,i,r,s)},hx=(n,e,t,i,r,s,o)=>{n.bezierCurveTo(e,t,i,r,s,o)},fx=(n,e,t,i,r,s,o)=>{n.bezierCurveTo(t,e,r,i,o,s)};function dx(n){return(e,t,i,r,s)=>Ls(e,t,(o,a,l,c,u,h,f,d,p,x,m)=>{let{pxRound:g,points:b}=o,T,v;c.ori==0?(T=Vc,v=cx):(T=Gc,v=ux);let R=Ht(b.width*Ct,3),A=(b.size-b.width)/2*Ct,_=Ht(A*2,3),E=new Path2D,F=new Path2D,{left:N,top:P,width:k,height:H}=e.bbox;zc(F,N-_,P-_,k+_*2,H+_*2);let D=W=>{if(l[W]!=null){let K=g(h(a[W],c,x,d)),z=g(f(l[W],u,m,p));T(E,K+A,z),v(E,K,z,A,0,Nc*2)}};if(s)s.forEach(D);else for(let W=i;W<=r;W++)D(W);return{stroke:R>0?E:null,fill:E,clip:F,flags:vo|Gd}})}function px(n){return(e,t,i,r,s,o)=>{i!=r&&(s!=i&&o!=i&&n(e,t,i),s!=r&&o!=r&&n(e,t,r),n(e,t,o))}}var TT=px(Eo),AT=px(Mo);function mx(n){let e=Rt(n?.alignGaps,0);return(t,i,r,s)=>Ls(t,i,(o,a,l,c,u,h,f,d,p,x,m)=>{[r,s]=Fc(l,r,s);let g=o.pxRound,b=H=>g(h(H,c,x,d)),T=H=>g(f(H,u,m,p)),v,R;c.ori==0?(v=Eo,R=TT):(v=Mo,R=AT);let A=c.dir*(c.ori==0?1:-1),_={stroke:new Path2D,fill:null,clip:null,band:null,gaps:null,flags:vo},E=_.stroke,F=!1;if(s-r>=x*4){let H=he=>t.posToVal(he,c.key,!0),D=null,W=null,K,z,ce,J=b(a[A==1?r:s]),Q=b(a[r]),re=b(a[s]),fe=H(A==1?Q+1:re-1);for(let he=A==1?r:s;he>=r&&he<=s;he+=A){let ee=a[he],ye=(A==1?ee<fe:ee>fe)?J:b(ee),Ae=l[he];ye==J?Ae!=null?(z=Ae,D==null?(v(E,ye,T(z)),K=D=W=z):z<D?D=z:z>W&&(W=z)):Ae===null&&(F=!0):(D!=null&&R(E,J,T(D),T(W),T(K),T(z)),Ae!=null?(z=Ae,v(E,ye,T(z)),D=W=K=z):(D=W=null,Ae===null&&(F=!0)),J=ye,fe=H(J+A))}D!=null&&D!=W&&ce!=J&&R(E,J,T(D),T(W),T(K),T(z))}else for(let H=A==1?r:s;H>=r&&H<=s;H+=A){let D=l[H];D===null?F=!0:D!=null&&v(E,b(a[H]),T(D))}let[P,k]=tp(t,i);if(o.fill!=null||P!=0){let H=_.fill=new Path2D(E),D=o.fillTo(t,i,o.min,o.max,P),W=T(D),K=b(a[r]),z=b(a[s]);A==-1&&([z,K]=[K,z]),v(H,z,W),v(H,K,W)}if(!o.spanGaps){let H=[];F&&H.push(...np(a,l,r,s,A,b,e)),_.gaps=H=o.gaps(t,i,r,s,H),_.clip=kc(H,c.ori,d,p,x,m)}return k!=0&&(_.band=k==2?[Nr(t,i,r,s,E,-1),Nr(t,i,r,s,E,1)]:Nr(t,i,r,s,E,k)),_})}function RT(n){let e=Rt(n.align,1),t=Rt(n.ascDesc,!1),i=Rt(n.alignGaps,0),r=Rt(n.extend,!1);return(s,o,a,l)=>Ls(s,o,(c,u,h,f,d,p,x,m,g,b,T)=>{[a,l]=Fc(h,a,l);let v=c.pxRound,{left:R,width:A}=s.bbox,_=Q=>v(p(Q,f,b,m)),E=Q=>v(x(Q,d,T,g)),F=f.ori==0?Eo:Mo,N={stroke:new Path2D,fill:null,clip:null,band:null,gaps:null,flags:vo},P=N.stroke,k=f.dir*(f.ori==0?1:-1),H=E(h[k==1?a:l]),D=_(u[k==1?a:l]),W=D,K=D;r&&e==-1&&(K=R,F(P,K,H)),F(P,D,H);for(let Q=k==1?a:l;Q>=a&&Q<=l;Q+=k){let re=h[Q];if(re==null)continue;let fe=_(u[Q]),he=E(re);e==1?F(P,fe,H):F(P,W,he),F(P,fe,he),H=he,W=fe}let z=W;r&&e==1&&(z=R+A,F(P,z,H));let[ce,J]=tp(s,o);if(c.fill!=null||ce!=0){let Q=N.fill=new Path2D(P),re=c.fillTo(s,o,c.min,c.max,ce),fe=E(re);F(Q,z,fe),F(Q,K,fe)}if(!c.spanGaps){let Q=[];Q.push(...np(u,h,a,l,k,_,i));let re=c.width*Ct/2,fe=t||e==1?re:-re,he=t||e==-1?-re:re;Q.forEach(ee=>{ee[0]+=fe,ee[1]+=he}),N.gaps=Q=c.gaps(s,o,a,l,Q),N.clip=kc(Q,f.ori,m,g,b,T)}return J!=0&&(N.band=J==2?[Nr(s,o,a,l,P,-1),Nr(s,o,a,l,P,1)]:Nr(s,o,a,l,P,J)),N})}function Iy(n,e,t,i,r,s,o=zt){if(n.length>1){let a=null;for(let l=0,c=1/0;l<n.length;l++)if(e[l]!==void 0){if(a!=null){let u=Rn(n[l]-n[a]);u<c&&(c=u,o=Rn(t(n[l],i,r,s)-t(n[a],i,r,s)))}a=l}}return o}function IT(n){n=n||za;let e=Rt(n.size,[.6,zt,1]),t=n.align||0,i=n.gap||0,r=n.radius;r=r==null?[0,0]:typeof r=="number"?[r,0]:r;let s=vt(r),o=1-e[0],a=Rt(e[1],zt),l=Rt(e[2],1),c=Rt(n.disp,za),u=Rt(n.each,d=>{}),{fill:h,stroke:f}=c;return(d,p,x,m)=>Ls(d,p,(g,b,T,v,R,A,_,E,F,N,P)=>{let k=g.pxRound,H=t,D=i*Ct,W=a*Ct,K=l*Ct,z,ce;v.ori==0?[z,ce]=s(d,p):[ce,z]=s(d,p);let J=v.dir*(v.ori==0?1:-1),Q=v.ori==0?zc:ip,re=v.ori==0?u:(Ie,qe,at,Ee,Vt,Ge,Ze)=>{u(Ie,qe,at,Vt,Ee,Ze,Ge)},fe=Rt(d.bands,qd).find(Ie=>Ie.series[0]==p),he=fe!=null?fe.dir:0,ee=g.fillTo(d,p,g.min,g.max,he),me=k(_(ee,R,P,F)),ye,Ae,Se,Xe=N,ot=k(g.width*Ct),ze=!1,ft=null,ct=null,rt=null,Qt=null;h!=null&&(ot==0||f!=null)&&(ze=!0,ft=h.values(d,p,x,m),ct=new Map,new Set(ft).forEach(Ie=>{Ie!=null&&ct.set(Ie,new Path2D)}),ot>0&&(rt=f.values(d,p,x,m),Qt=new Map,new Set(rt).forEach(Ie=>{Ie!=null&&Qt.set(Ie,new Path2D)})));let{x0:Xt,size:mn}=c;if(Xt!=null&&mn!=null){H=1,b=Xt.values(d,p,x,m),Xt.unit==2&&(b=b.map(at=>d.posToVal(E+at*N,v.key,!0)));let Ie=mn.values(d,p,x,m);mn.unit==2?Ae=Ie[0]*N:Ae=A(Ie[0],v,N,E)-A(0,v,N,E),Xe=Iy(b,T,A,v,N,E,Xe),Se=Xe-Ae+D}else Xe=Iy(b,T,A,v,N,E,Xe),Se=Xe*o+D,Ae=Xe-Se;Se<1&&(Se=0),ot>=Ae/2&&(ot=0),Se<5&&(k=By);let Ot=Se>0,Ln=Xe-Se-(Ot?ot:0);Ae=k(Bd(Ln,K,W)),ye=(H==0?Ae/2:H==J?0:Ae)-H*J*((H==0?D/2:0)+(Ot?ot/2:0));let wt={stroke:null,fill:null,clip:null,band:null,gaps:null,flags:0},Mn=ze?null:new Path2D,sn=null;if(fe!=null)sn=d.data[fe.series[1]];else{let{y0:Ie,y1:qe}=c;Ie!=null&&qe!=null&&(T=qe.values(d,p,x,m),sn=Ie.values(d,p,x,m))}let gn=z*Ae,O=ce*Ae;for(let Ie=J==1?x:m;Ie>=x&&Ie<=m;Ie+=J){let qe=T[Ie];if(qe==null)continue;if(sn!=null){let Y=sn[Ie]??0;if(qe-Y==0)continue;me=_(Y,R,P,F)}let at=v.distr!=2||c!=null?b[Ie]:Ie,Ee=A(at,v,N,E),Vt=_(Rt(qe,ee),R,P,F),Ge=k(Ee-ye),Ze=k(ni(Vt,me)),I=k(Yi(Vt,me)),S=Ze-I;if(qe!=null){let Y=qe<0?O:gn,ue=qe<0?gn:O;ze?(ot>0&&rt[Ie]!=null&&Q(Qt.get(rt[Ie]),Ge,I+yi(ot/2),Ae,ni(0,S-ot),Y,ue),ft[Ie]!=null&&Q(ct.get(ft[Ie]),Ge,I+yi(ot/2),Ae,ni(0,S-ot),Y,ue)):Q(Mn,Ge,I+yi(ot/2),Ae,ni(0,S-ot),Y,ue),re(d,p,Ie,Ge-ot/2,I,Ae+ot,S)}}return ot>0?wt.stroke=ze?Qt:Mn:ze||(wt._fill=g.width==0?g._fill:g._stroke??g._fill,wt.width=0),wt.fill=ze?ct:Mn,wt})}function CT(n,e){let t=Rt(e?.alignGaps,0);return(i,r,s,o)=>Ls(i,r,(a,l,c,u,h,f,d,p,x,m,g)=>{[s,o]=Fc(c,s,o);let b=a.pxRound,T=z=>b(f(z,u,m,p)),v=z=>b(d(z,h,g,x)),R,A,_;u.ori==0?(R=Vc,_=Eo,A=hx):(R=Gc,_=Mo,A=fx);let E=u.dir*(u.ori==0?1:-1),F=T(l[E==1?s:o]),N=F,P=[],k=[];for(let z=E==1?s:o;z>=s&&z<=o;z+=E)if(c[z]!=null){let J=l[z],Q=T(J);P.push(N=Q),k.push(v(c[z]))}let H={stroke:n(P,k,R,_,A,b),fill:null,clip:null,band:null,gaps:null,flags:vo},D=H.stroke,[W,K]=tp(i,r);if(a.fill!=null||W!=0){let z=H.fill=new Path2D(D),ce=a.fillTo(i,r,a.min,a.max,W),J=v(ce);_(z,N,J),_(z,F,J)}if(!a.spanGaps){let z=[];z.push(...np(l,c,s,o,E,T,t)),H.gaps=z=a.gaps(i,r,s,o,z),H.clip=kc(z,u.ori,p,x,m,g)}return K!=0&&(H.band=K==2?[Nr(i,r,s,o,D,-1),Nr(i,r,s,o,D,1)]:Nr(i,r,s,o,D,K)),H})}function NT(n){return CT(PT,n)}function PT(n,e,t,i,r,s){let o=n.length;if(o<2)return null;let a=new Path2D;if(t(a,n[0],e[0]),o==2)i(a,n[1],e[1]);else{let l=Array(o),c=Array(o-1),u=Array(o-1),h=Array(o-1);for(let f=0;f<o-1;f++)u[f]=e[f+1]-e[f],h[f]=n[f+1]-n[f],c[f]=u[f]/h[f];l[0]=c[0];for(let f=1;f<o-1;f++)c[f]===0||c[f-1]===0||c[f-1]>0!=c[f]>0?l[f]=0:(l[f]=3*(h[f-1]+h[f])/((2*h[f]+h[f-1])/c[f-1]+(h[f]+2*h[f-1])/c[f]),isFinite(l[f])||(l[f]=0));l[o-1]=c[o-2];for(let f=0;f<o-1;f++)r(a,n[f]+h[f]/3,e[f]+l[f]*h[f]/3,n[f+1]-h[f]/3,e[f+1]-l[f+1]*h[f]/3,n[f+1],e[f+1])}return a}var zd=new Set;function Cy(){for(let n of zd)n.syncRect(!0)}So&&(Ns(fw,_o,Cy),Ns(dw,_o,Cy,!0),Ns(Pc,_o,()=>{Wn.pxRatio=Ct}));var LT=mx(),DT=dx();function Ny(n,e,t,i){return(i?[n[0],n[1]].concat(n.slice(2)):[n[0]].concat(n.slice(1))).map((s,o)=>Hd(s,o,e,t))}function FT(n,e){return n.map((t,i)=>i==0?{}:Sn({},e,t))}function Hd(n,e,t,i){return Sn({},e==0?t:i,n)}function gx(n,e,t){return e==null?xo:[e,t]}var UT=gx;function OT(n,e,t){return e==null?xo:Lc(e,t,Kd,!0)}function _x(n,e,t,i){return e==null?xo:Uc(e,t,n.scales[i].log,!1)}var BT=_x;function yx(n,e,t,i){return e==null?xo:Zd(e,t,n.scales[i].log,!1)}var kT=yx;function VT(n,e,t,i,r){let s=ni(cy(n),cy(e)),o=e-n,a=Xi(r/i*o,t);do{let l=t[a],c=i*l/o;if(c>=r&&s+(l<5?is.get(l):0)<=17)return[l,c]}while(++a<t.length);return[0,0]}function Py(n){let e,t;return n=n.replace(/(\d+)px/,(i,r)=>(e=An((t=+r)*Ct))+"px"),[n,e,t]}function GT(n){n.show&&[n.font,n.labelFont].forEach(e=>{let t=Ht(e[2]*Ct,1);e[0]=e[0].replace(/[0-9.]+px/,t+"px"),e[1]=t})}function Wn(n,e,t){let i={mode:Rt(n.mode,1)},r=i.mode;function s(y,M,C,L){let G=M.valToPct(y);return L+C*(M.dir==-1?1-G:G)}function o(y,M,C,L){let G=M.valToPct(y);return L+C*(M.dir==-1?G:1-G)}function a(y,M,C,L){return M.ori==0?s(y,M,C,L):o(y,M,C,L)}i.valToPosH=s,i.valToPosV=o;let l=!1;i.status=0;let c=i.root=Ni(KM);if(n.id!=null&&(c.id=n.id),_i(c,n.class),n.title){let y=Ni(JM,c);y.textContent=n.title}let u=Wi("canvas"),h=i.ctx=u.getContext("2d"),f=Ni(jM,c);Ns("click",f,y=>{y.target===p&&(Zt!=Qs||en!=eo)&&zn.click(i,y)},!0);let d=i.under=Ni(QM,f);f.appendChild(u);let p=i.over=Ni(ew,f);n=bo(n);let x=+Rt(n.pxAlign,1),m=Ry(x);(n.plugins||[]).forEach(y=>{y.opts&&(n=y.opts(i,n)||n)});let g=n.ms||.001,b=i.series=r==1?Ny(n.series||[],vy,Ty,!1):FT(n.series||[null],wy),T=i.axes=Ny(n.axes||[],by,Ey,!0),v=i.scales={},R=i.bands=n.bands||[];R.forEach(y=>{y.fill=vt(y.fill||null),y.dir=Rt(y.dir,-1)});let A=r==2?b[1].facets[0].scale:b[0].scale,_={axes:wr,series:gt},E=(n.drawOrder||["axes","series"]).map(y=>_[y]);function F(y){let M=y.distr==3?C=>Cr(C>0?C:y.clamp(i,C,y.min,y.max,y.key)):y.distr==4?C=>Cd(C,y.asinh):y.distr==100?C=>y.fwd(C):C=>C;return C=>{let L=M(C),{_min:G,_max:q}=y,ae=q-G;return(L-G)/ae}}function N(y){let M=v[y];if(M==null){let C=(n.scales||za)[y]||za;if(C.from!=null){N(C.from);let L=Sn({},v[C.from],C,{key:y});L.valToPct=F(L),v[y]=L}else{M=v[y]=Sn({},y==A?ox:ET,C),M.key=y;let L=M.time,G=M.range,q=ns(G);if((y!=A||r==2&&!L)&&(q&&(G[0]==null||G[1]==null)&&(G={min:G[0]==null?oy:{mode:1,hard:G[0],soft:G[0]},max:G[1]==null?oy:{mode:1,hard:G[1],soft:G[1]}},q=!1),!q&&Bc(G))){let ae=G;G=(de,be,Le)=>be==null?xo:Lc(be,Le,ae)}M.range=vt(G||(L?UT:y==A?M.distr==3?BT:M.distr==4?kT:gx:M.distr==3?_x:M.distr==4?yx:OT)),M.auto=vt(q?!1:M.auto),M.clamp=vt(M.clamp||ST),M._min=M._max=null,M.valToPct=F(M)}}}N("x"),N("y"),r==1&&b.forEach(y=>{N(y.scale)}),T.forEach(y=>{N(y.scale)});for(let y in n.scales)N(y);let P=v[A],k=P.distr,H,D;P.ori==0?(_i(c,$M),H=s,D=o):(_i(c,qM),H=o,D=s);let W={};for(let y in v){let M=v[y];(M.min!=null||M.max!=null)&&(W[y]={min:M.min,max:M.max},M.min=M.max=null)}let K=n.tzDate||(y=>new Date(An(y/g))),z=n.fmtDate||Jd,ce=g==1?$w(K):jw(K),J=_y(K,gy(g==1?Kw:Jw,z)),Q=xy(K,yy(eT,z)),re=[],fe=i.legend=Sn({},iT,n.legend),he=i.cursor=Sn({},cT,{drag:{y:r==2}},n.cursor),ee=fe.show,me=he.show,ye=fe.markers;fe.idxs=re,ye.width=vt(ye.width),ye.dash=vt(ye.dash),ye.stroke=vt(ye.stroke),ye.fill=vt(ye.fill);let Ae,Se,Xe,ot=[],ze=[],ft,ct=!1,rt={};if(fe.live){let y=b[1]?b[1].values:null;ct=y!=null,ft=ct?y(i,1,0):{_:0};for(let M in ft)rt[M]=Xd}if(ee)if(Ae=Wi("table",ow,c),Xe=Wi("tbody",null,Ae),fe.mount(i,Ae),ct){Se=Wi("thead",null,Ae,Xe);let y=Wi("tr",null,Se);Wi("th",null,y);for(var Qt in ft)Wi("th",Z_,y).textContent=Qt}else _i(Ae,lw),fe.live&&_i(Ae,aw);let Xt={show:!0},mn={show:!1};function Ot(y,M){if(M==0&&(ct||!fe.live||r==2))return xo;let C=[],L=Wi("tr",cw,Xe,Xe.childNodes[M]);_i(L,y.class),y.show||_i(L,Cs);let G=Wi("th",null,L);if(ye.show){let de=Ni(uw,G);if(M>0){let be=ye.width(i,M);be&&(de.style.border=be+"px "+ye.dash(i,M)+" "+ye.stroke(i,M)),de.style.background=ye.fill(i,M)}}let q=Ni(Z_,G);y.label instanceof HTMLElement?q.appendChild(y.label):q.textContent=y.label,M>0&&(ye.show||(q.style.color=y.width>0?ye.stroke(i,M):ye.fill(i,M)),wt("click",G,de=>{if(he._lock)return;je(de);let be=b.indexOf(y);if((de.ctrlKey||de.metaKey)!=fe.isolate){let Le=b.some((De,Ue)=>Ue>0&&Ue!=be&&De.show);b.forEach((De,Ue)=>{Ue>0&&or(Ue,Le?Ue==be?Xt:mn:Xt,!0,bn.setSeries)})}else or(be,{show:!y.show},!0,bn.setSeries)},!1),Qe&&wt(J_,G,de=>{he._lock||(je(de),or(b.indexOf(y),no,!0,bn.setSeries))},!1));for(var ae in ft){let de=Wi("td",hw,L);de.textContent="--",C.push(de)}return[L,C]}let Ln=new Map;function wt(y,M,C,L=!0){let G=Ln.get(M)||{},q=he.bind[y](i,M,C,L);q&&(Ns(y,M,G[y]=q),Ln.set(M,G))}function Mn(y,M,C){let L=Ln.get(M)||{};for(let G in L)(y==null||G==y)&&(Od(G,M,L[G]),delete L[G]);y==null&&Ln.delete(M)}let sn=0,gn=0,O=0,Ie=0,qe=0,at=0,Ee=qe,Vt=at,Ge=O,Ze=Ie,I=0,S=0,Y=0,ue=0;i.bbox={};let oe=!1,_e=!1,xe=!1,te=!1,ie=!1,pe=!1;function U(y,M,C){(C||y!=i.width||M!=i.height)&&se(y,M),ut(!1),xe=!0,_e=!0,Yn()}function se(y,M){i.width=sn=O=y,i.height=gn=Ie=M,qe=at=0,ve(),He();let C=i.bbox;I=C.left=Rs(qe*Ct,.5),S=C.top=Rs(at*Ct,.5),Y=C.width=Rs(O*Ct,.5),ue=C.height=Rs(Ie*Ct,.5)}let ne=3;function Me(){let y=!1,M=0;for(;!y;){M++;let C=qs(M),L=sr(M);y=M==ne||C&&L,y||(se(i.width,i.height),_e=!0)}}function ge({width:y,height:M}){U(y,M)}i.setSize=ge;function ve(){let y=!1,M=!1,C=!1,L=!1;T.forEach((G,q)=>{if(G.show&&G._show){let{side:ae,_size:de}=G,be=ae%2,Le=G.label!=null?G.labelSize:0,De=de+Le;De>0&&(be?(O-=De,ae==3?(qe+=De,L=!0):C=!0):(Ie-=De,ae==0?(at+=De,y=!0):M=!0))}}),ir[0]=y,ir[1]=C,ir[2]=M,ir[3]=L,O-=Bi[1]+Bi[3],qe+=Bi[3],Ie-=Bi[2]+Bi[0],at+=Bi[0]}function He(){let y=qe+O,M=at+Ie,C=qe,L=at;function G(q,ae){switch(q){case 1:return y+=ae,y-ae;case 2:return M+=ae,M-ae;case 3:return C-=ae,C+ae;case 0:return L-=ae,L+ae}}T.forEach((q,ae)=>{if(q.show&&q._show){let de=q.side;q._pos=G(de,q._size),q.label!=null&&(q._lpos=G(de,q.labelSize))}})}if(he.dataIdx==null){let y=he.hover,M=y.skip=new Set(y.skip??[]);M.add(void 0);let C=y.prox=vt(y.prox),L=y.bias??=0;he.dataIdx=(G,q,ae,de)=>{if(q==0)return ae;let be=ae,Le=C(G,q,ae,de)??zt,De=Le>=0&&Le<zt,Ue=P.ori==0?O:Ie,st=he.left,It=e[0],At=e[q];if(M.has(At[ae])){be=null;let yt=null,Je=null,Ye;if(L==0||L==-1)for(Ye=ae;yt==null&&Ye-- >0;)M.has(At[Ye])||(yt=Ye);if(L==0||L==1)for(Ye=ae;Je==null&&Ye++<At.length;)M.has(At[Ye])||(Je=Ye);if(yt!=null||Je!=null)if(De){let $t=yt==null?-1/0:H(It[yt],P,Ue,0),ln=Je==null?1/0:H(It[Je],P,Ue,0),On=st-$t,Bt=ln-st;On<=Bt?On<=Le&&(be=yt):Bt<=Le&&(be=Je)}else be=Je==null?yt:yt==null?Je:ae-yt<=Je-ae?yt:Je}else De&&Rn(st-H(It[ae],P,Ue,0))>Le&&(be=null);return be}}let je=y=>{he.event=y};he.idxs=re,he._lock=!1;let le=he.points;le.show=vt(le.show),le.size=vt(le.size),le.stroke=vt(le.stroke),le.width=vt(le.width),le.fill=vt(le.fill);let Be=i.focus=Sn({},n.focus||{alpha:.3},he.focus),Qe=Be.prox>=0,Re=Qe&&le.one,lt=[],Yt=[],Jn=[];function pa(y,M){let C=le.show(i,M);if(C instanceof HTMLElement)return _i(C,sw),_i(C,y.class),dr(C,-10,-10,O,Ie),p.insertBefore(C,lt[M]),C}function Zs(y,M){if(r==1||M>0){let C=r==1&&v[y.scale].time,L=y.value;y.value=C?fy(L)?xy(K,yy(L,z)):L||Q:L||xT,y.label=y.label||(C?hT:uT)}if(Re||M>0){y.width=y.width==null?1:y.width,y.paths=y.paths||LT||Ew,y.fillTo=vt(y.fillTo||MT),y.pxAlign=+Rt(y.pxAlign,x),y.pxRound=Ry(y.pxAlign),y.stroke=vt(y.stroke||null),y.fill=vt(y.fill||null),y._stroke=y._fill=y._paths=y._focus=null;let C=bT(ni(1,y.width),1),L=y.points=Sn({},{size:C,width:ni(1,C*.2),stroke:y.stroke,space:C*2,paths:DT,_stroke:null,_fill:null},y.points);L.show=vt(L.show),L.filter=vt(L.filter),L.fill=vt(L.fill),L.stroke=vt(L.stroke),L.paths=vt(L.paths),L.pxAlign=y.pxAlign}if(ee){let C=Ot(y,M);ot.splice(M,0,C[0]),ze.splice(M,0,C[1]),fe.values.push(null)}if(me){re.splice(M,0,null);let C=null;Re?M==0&&(C=pa(y,M)):M>0&&(C=pa(y,M)),lt.splice(M,0,C),Yt.splice(M,0,0),Jn.splice(M,0,0)}Un("addSeries",M)}function ff(y,M){M=M??b.length,y=r==1?Hd(y,M,vy,Ty):Hd(y,M,{},wy),b.splice(M,0,y),Zs(b[M],M)}i.addSeries=ff;function zl(y){if(b.splice(y,1),ee){fe.values.splice(y,1),ze.splice(y,1);let M=ot.splice(y,1)[0];Mn(null,M.firstChild),M.remove()}me&&(re.splice(y,1),lt.splice(y,1)[0].remove(),Yt.splice(y,1),Jn.splice(y,1)),Un("delSeries",y)}i.delSeries=zl;let ir=[!1,!1,!1,!1];function Sr(y,M){if(y._show=y.show,y.show){let C=y.side%2,L=v[y.scale];L==null&&(y.scale=C?b[1].scale:A,L=v[y.scale]);let G=L.time;y.size=vt(y.size),y.space=vt(y.space),y.rotate=vt(y.rotate),ns(y.incrs)&&y.incrs.forEach(ae=>{!is.has(ae)&&is.set(ae,Gy(ae))}),y.incrs=vt(y.incrs||(L.distr==2?Xw:G?g==1?Zw:qw:Is)),y.splits=vt(y.splits||(G&&L.distr==1?ce:L.distr==3?kd:L.distr==4?pT:dT)),y.stroke=vt(y.stroke),y.grid.stroke=vt(y.grid.stroke),y.ticks.stroke=vt(y.ticks.stroke),y.border.stroke=vt(y.border.stroke);let q=y.values;y.values=ns(q)&&!ns(q[0])?vt(q):G?ns(q)?_y(K,gy(q,z)):fy(q)?Qw(K,q):q||J:q||fT,y.filter=vt(y.filter||(L.distr>=3&&L.log==10?_T:L.distr==3&&L.log==2?yT:ky)),y.font=Py(y.font),y.labelFont=Py(y.labelFont),y._size=y.size(i,null,M,0),y._space=y._rotate=y._incrs=y._found=y._splits=y._values=null,y._size>0&&(ir[M]=!0,y._el=Ni(tw,f))}}function Er(y,M,C,L){let[G,q,ae,de]=C,be=M%2,Le=0;return be==0&&(de||q)&&(Le=M==0&&!G||M==2&&!ae?An(by.size/3):0),be==1&&(G||ae)&&(Le=M==1&&!q||M==3&&!de?An(Ey.size/2):0),Le}let ma=i.padding=(n.padding||[Er,Er,Er,Er]).map(y=>vt(Rt(y,Er))),Bi=i._padding=ma.map((y,M)=>y(i,M,ir,0)),on,fn=null,dn=null,rr=r==1?b[0].idxs:null,hi=null,$r=!1;function ga(y,M){if(e=y??[],i.data=i._data=e,r==2){on=0;for(let C=1;C<b.length;C++)on+=e[C][0].length}else{e.length==0&&(i.data=i._data=e=[[]]),hi=e[0],on=hi.length;let C=e;if(k==2){C=e.slice();let L=C[0]=Array(on);for(let G=0;G<on;G++)L[G]=G}i._data=e=C}if(ut(!0),Un("setData"),k==2&&(xe=!0),M!==!1){let C=P;C.auto(i,$r)?_a():jr(A,C.min,C.max),te=te||he.left>=0,pe=!0,Yn()}}i.setData=ga;function _a(){$r=!0;let y,M;r==1&&(on>0?(fn=rr[0]=0,dn=rr[1]=on-1,y=e[0][fn],M=e[0][dn],k==2?(y=fn,M=dn):y==M&&(k==3?[y,M]=Uc(y,y,P.log,!1):k==4?[y,M]=Zd(y,y,P.log,!1):P.time?M=y+An(86400/g):[y,M]=Lc(y,M,Kd,!0))):(fn=rr[0]=y=null,dn=rr[1]=M=null)),jr(A,y,M)}let Ks,qr,$s,w,B,j,Z,$,we,Ce;function Te(y,M,C,L,G,q){y??=$_,C??=qd,L??="butt",G??=$_,q??="round",y!=Ks&&(h.strokeStyle=Ks=y),G!=qr&&(h.fillStyle=qr=G),M!=$s&&(h.lineWidth=$s=M),q!=B&&(h.lineJoin=B=q),L!=j&&(h.lineCap=j=L),C!=w&&h.setLineDash(w=C)}function Ne(y,M,C,L){M!=qr&&(h.fillStyle=qr=M),y!=Z&&(h.font=Z=y),C!=$&&(h.textAlign=$=C),L!=we&&(h.textBaseline=we=L)}function Ve(y,M,C,L,G=0){if(L.length>0&&y.auto(i,$r)&&(M==null||M.min==null)){let q=Rt(fn,0),ae=Rt(dn,L.length-1),de=C.min==null?_w(L,q,ae,G,y.distr==3):[C.min,C.max];y.min=Yi(y.min,C.min=de[0]),y.max=ni(y.max,C.max=de[1])}}let nt={min:null,max:null};function mt(){for(let L in v){let G=v[L];W[L]==null&&(G.min==null||W[A]!=null&&G.auto(i,$r))&&(W[L]=nt)}for(let L in v){let G=v[L];W[L]==null&&G.from!=null&&W[G.from]!=null&&(W[L]=nt)}W[A]!=null&&ut(!0);let y={};for(let L in W){let G=W[L];if(G!=null){let q=y[L]=bo(v[L],Tw);if(G.min!=null)Sn(q,G);else if(L!=A||r==2)if(on==0&&q.from==null){let ae=q.range(i,null,null,L);q.min=ae[0],q.max=ae[1]}else q.min=zt,q.max=-zt}}if(on>0){b.forEach((L,G)=>{if(r==1){let q=L.scale,ae=W[q];if(ae==null)return;let de=y[q];if(G==0){let be=de.range(i,de.min,de.max,q);de.min=be[0],de.max=be[1],fn=Xi(de.min,e[0]),dn=Xi(de.max,e[0]),dn-fn>1&&(e[0][fn]<de.min&&fn++,e[0][dn]>de.max&&dn--),L.min=hi[fn],L.max=hi[dn]}else L.show&&L.auto&&Ve(de,ae,L,e[G],L.sorted);L.idxs[0]=fn,L.idxs[1]=dn}else if(G>0&&L.show&&L.auto){let[q,ae]=L.facets,de=q.scale,be=ae.scale,[Le,De]=e[G],Ue=y[de],st=y[be];Ue!=null&&Ve(Ue,W[de],q,Le,q.sorted),st!=null&&Ve(st,W[be],ae,De,ae.sorted),L.min=ae.min,L.max=ae.max}});for(let L in y){let G=y[L],q=W[L];if(G.from==null&&(q==null||q.min==null)){let ae=G.range(i,G.min==zt?null:G.min,G.max==-zt?null:G.max,L);G.min=ae[0],G.max=ae[1]}}}for(let L in y){let G=y[L];if(G.from!=null){let q=y[G.from];if(q.min==null)G.min=G.max=null;else{let ae=G.range(i,q.min,q.max,L);G.min=ae[0],G.max=ae[1]}}}let M={},C=!1;for(let L in y){let G=y[L],q=v[L];if(q.min!=G.min||q.max!=G.max){q.min=G.min,q.max=G.max;let ae=q.distr;q._min=ae==3?Cr(q.min):ae==4?Cd(q.min,q.asinh):ae==100?q.fwd(q.min):q.min,q._max=ae==3?Cr(q.max):ae==4?Cd(q.max,q.asinh):ae==100?q.fwd(q.max):q.max,M[L]=C=!0}}if(C){b.forEach((L,G)=>{r==2?G>0&&M.y&&(L._paths=null):M[L.scale]&&(L._paths=null)});for(let L in M)xe=!0,Un("setScale",L);me&&he.left>=0&&(te=pe=!0)}for(let L in W)W[L]=null}function ke(y){let M=Bd(fn-1,0,on-1),C=Bd(dn+1,0,on-1);for(;y[M]==null&&M>0;)M--;for(;y[C]==null&&C<on-1;)C++;return[M,C]}function gt(){if(on>0){let y=b.some(M=>M._focus)&&Ce!=Be.alpha;y&&(h.globalAlpha=Ce=Be.alpha),b.forEach((M,C)=>{if(C>0&&M.show&&(rn(C,!1),rn(C,!0),M._paths==null)){let L=Ce;Ce!=M.alpha&&(h.globalAlpha=Ce=M.alpha);let G=r==2?[0,e[C][0].length-1]:ke(e[C]);M._paths=M.paths(i,C,G[0],G[1]),Ce!=L&&(h.globalAlpha=Ce=L)}}),b.forEach((M,C)=>{if(C>0&&M.show){let L=Ce;Ce!=M.alpha&&(h.globalAlpha=Ce=M.alpha),M._paths!=null&&Dt(C,!1);{let G=M._paths!=null?M._paths.gaps:null,q=M.points.show(i,C,fn,dn,G),ae=M.points.filter(i,C,q,G);(q||ae)&&(M.points._paths=M.points.paths(i,C,fn,dn,ae),Dt(C,!0))}Ce!=L&&(h.globalAlpha=Ce=L),Un("drawSeries",C)}}),y&&(h.globalAlpha=Ce=1)}}function rn(y,M){let C=M?b[y].points:b[y];C._stroke=C.stroke(i,y),C._fill=C.fill(i,y)}function Dt(y,M){let C=M?b[y].points:b[y],{stroke:L,fill:G,clip:q,flags:ae,_stroke:de=C._stroke,_fill:be=C._fill,_width:Le=C.width}=C._paths;Le=Ht(Le*Ct,3);let De=null,Ue=Le%2/2;M&&be==null&&(be=Le>0?"#fff":de);let st=C.pxAlign==1&&Ue>0;if(st&&h.translate(Ue,Ue),!M){let It=I-Le/2,At=S-Le/2,yt=Y+Le,Je=ue+Le;De=new Path2D,De.rect(It,At,yt,Je)}M?Fe(de,Le,C.dash,C.cap,be,L,G,ae,q):Ft(y,de,Le,C.dash,C.cap,be,L,G,ae,De,q),st&&h.translate(-Ue,-Ue)}function Ft(y,M,C,L,G,q,ae,de,be,Le,De){let Ue=!1;be!=0&&R.forEach((st,It)=>{if(st.series[0]==y){let At=b[st.series[1]],yt=e[st.series[1]],Je=(At._paths||za).band;ns(Je)&&(Je=st.dir==1?Je[0]:Je[1]);let Ye,$t=null;At.show&&Je&&xw(yt,fn,dn)?($t=st.fill(i,It)||q,Ye=At._paths.clip):Je=null,Fe(M,C,L,G,$t,ae,de,be,Le,De,Ye,Je),Ue=!0}}),Ue||Fe(M,C,L,G,q,ae,de,be,Le,De)}let wn=vo|Gd;function Fe(y,M,C,L,G,q,ae,de,be,Le,De,Ue){Te(y,M,C,L,G),(be||Le||Ue)&&(h.save(),be&&h.clip(be),Le&&h.clip(Le)),Ue?(de&wn)==wn?(h.clip(Ue),De&&h.clip(De),bt(G,ae),_n(y,q,M)):de&Gd?(bt(G,ae),h.clip(Ue),_n(y,q,M)):de&vo&&(h.save(),h.clip(Ue),De&&h.clip(De),bt(G,ae),h.restore(),_n(y,q,M)):(bt(G,ae),_n(y,q,M)),(be||Le||Ue)&&h.restore()}function _n(y,M,C){C>0&&(M instanceof Map?M.forEach((L,G)=>{h.strokeStyle=Ks=G,h.stroke(L)}):M!=null&&y&&h.stroke(M))}function bt(y,M){M instanceof Map?M.forEach((C,L)=>{h.fillStyle=qr=L,h.fill(C)}):M!=null&&y&&h.fill(M)}function Mr(y,M,C,L){let G=T[y],q;if(L<=0)q=[0,0];else{let ae=G._space=G.space(i,y,M,C,L),de=G._incrs=G.incrs(i,y,M,C,L,ae);q=VT(M,C,de,L,ae)}return G._found=q}function yn(y,M,C,L,G,q,ae,de,be,Le){let De=ae%2/2;x==1&&h.translate(De,De),Te(de,ae,be,Le,de),h.beginPath();let Ue,st,It,At,yt=G+(L==0||L==3?-q:q);C==0?(st=G,At=yt):(Ue=G,It=yt);for(let Je=0;Je<y.length;Je++)M[Je]!=null&&(C==0?Ue=It=y[Je]:st=At=y[Je],h.moveTo(Ue,st),h.lineTo(It,At));h.stroke(),x==1&&h.translate(-De,-De)}function qs(y){let M=!0;return T.forEach((C,L)=>{if(!C.show)return;let G=v[C.scale];if(G.min==null){C._show&&(M=!1,C._show=!1,ut(!1));return}else C._show||(M=!1,C._show=!0,ut(!1));let q=C.side,ae=q%2,{min:de,max:be}=G,[Le,De]=Mr(L,de,be,ae==0?O:Ie);if(De==0)return;let Ue=G.distr==2,st=C._splits=C.splits(i,L,de,be,Le,De,Ue),It=G.distr==2?st.map(Ye=>hi[Ye]):st,At=G.distr==2?hi[st[1]]-hi[st[0]]:Le,yt=C._values=C.values(i,C.filter(i,It,L,De,At),L,De,At);C._rotate=q==2?C.rotate(i,yt,L,De):0;let Je=C._size;C._size=Pi(C.size(i,yt,L,y)),Je!=null&&C._size!=Je&&(M=!1)}),M}function sr(y){let M=!0;return ma.forEach((C,L)=>{let G=C(i,L,ir,y);G!=Bi[L]&&(M=!1),Bi[L]=G}),M}function wr(){for(let y=0;y<T.length;y++){let M=T[y];if(!M.show||!M._show)continue;let C=M.side,L=C%2,G,q,ae=M.stroke(i,y),de=C==0||C==3?-1:1,[be,Le]=M._found;if(M.label!=null){let ei=M.labelGap*de,pi=An((M._lpos+ei)*Ct);Ne(M.labelFont[0],ae,"center",C==2?"top":K_),h.save(),L==1?(G=q=0,h.translate(pi,An(S+ue/2)),h.rotate((C==3?-Nc:Nc)/2)):(G=An(I+Y/2),q=pi);let Ms=Oy(M.label)?M.label(i,y,be,Le):M.label;h.fillText(Ms,G,q),h.restore()}if(Le==0)continue;let De=v[M.scale],Ue=L==0?Y:ue,st=L==0?I:S,It=M._splits,At=De.distr==2?It.map(ei=>hi[ei]):It,yt=De.distr==2?hi[It[1]]-hi[It[0]]:be,Je=M.ticks,Ye=M.border,$t=Je.show?Je.size:0,ln=An($t*Ct),On=An((M.alignTo==2?M._size-$t-M.gap:M.gap)*Ct),Bt=M._rotate*-Nc/180,cn=m(M._pos*Ct),fi=(ln+On)*de,Qn=cn+fi;q=L==0?Qn:0,G=L==1?Qn:0;let Ri=M.font[0],ki=M.align==1?mo:M.align==2?Ad:Bt>0?mo:Bt<0?Ad:L==0?"center":C==3?Ad:mo,lr=Bt||L==1?"middle":C==2?"top":K_;Ne(Ri,ae,ki,lr);let di=M.font[1]*M.lineGap,Ii=It.map(ei=>m(a(ei,De,Ue,st))),Vi=M._values;for(let ei=0;ei<Vi.length;ei++){let pi=Vi[ei];if(pi!=null){L==0?G=Ii[ei]:q=Ii[ei],pi=""+pi;let Ms=pi.indexOf(`
`)==-1?[pi]:pi.split(/\n/gm);for(let ti=0;ti<Ms.length;ti++){let cg=Ms[ti];Bt?(h.save(),h.translate(G,q+ti*di),h.rotate(Bt),h.fillText(cg,0,0),h.restore()):h.fillText(cg,G,q+ti*di)}}}Je.show&&yn(Ii,Je.filter(i,At,y,Le,yt),L,C,cn,ln,Ht(Je.width*Ct,3),Je.stroke(i,y),Je.dash,Je.cap);let cr=M.grid;cr.show&&yn(Ii,cr.filter(i,At,y,Le,yt),L,L==0?2:1,L==0?S:I,L==0?ue:Y,Ht(cr.width*Ct,3),cr.stroke(i,y),cr.dash,cr.cap),Ye.show&&yn([cn],[1],L==0?1:0,L==0?1:2,L==1?S:I,L==1?ue:Y,Ht(Ye.width*Ct,3),Ye.stroke(i,y),Ye.dash,Ye.cap)}Un("drawAxes")}function ut(y){b.forEach((M,C)=>{C>0&&(M._paths=null,y&&(r==1?(M.min=null,M.max=null):M.facets.forEach(L=>{L.min=null,L.max=null})))})}let an=!1,jn=!1,Ut=[];function xn(){jn=!1;for(let y=0;y<Ut.length;y++)Un(...Ut[y]);Ut.length=0}function Yn(){an||(Lw(Xm),an=!0)}function Hl(y,M=!1){an=!0,jn=M,y(i),Xm(),M&&Ut.length>0&&queueMicrotask(xn)}i.batch=Hl;function Xm(){if(oe&&(mt(),oe=!1),xe&&(Me(),xe=!1),_e){if(qt(d,mo,qe),qt(d,"top",at),qt(d,Ba,O),qt(d,ka,Ie),qt(p,mo,qe),qt(p,"top",at),qt(p,Ba,O),qt(p,ka,Ie),qt(f,Ba,sn),qt(f,ka,gn),u.width=An(sn*Ct),u.height=An(gn*Ct),T.forEach(({_el:y,_show:M,_size:C,_pos:L,side:G})=>{if(y!=null)if(M){let q=G===3||G===0?C:0,ae=G%2==1;qt(y,ae?"left":"top",L-q),qt(y,ae?"width":"height",C),qt(y,ae?"top":"left",ae?at:qe),qt(y,ae?"height":"width",ae?Ie:O),Ud(y,Cs)}else _i(y,Cs)}),Ks=qr=$s=B=j=Z=$=we=w=null,Ce=1,ba(!0),qe!=Ee||at!=Vt||O!=Ge||Ie!=Ze){ut(!1);let y=O/Ge,M=Ie/Ze;if(me&&!te&&he.left>=0){he.left*=y,he.top*=M,Js&&dr(Js,An(he.left),0,O,Ie),js&&dr(js,0,An(he.top),O,Ie);for(let C=0;C<lt.length;C++){let L=lt[C];L!=null&&(Yt[C]*=y,Jn[C]*=M,dr(L,Pi(Yt[C]),Pi(Jn[C]),O,Ie))}}if(Kt.show&&!ie&&Kt.left>=0&&Kt.width>0){Kt.left*=y,Kt.width*=y,Kt.top*=M,Kt.height*=M;for(let C in yf)qt(to,C,Kt[C])}Ee=qe,Vt=at,Ge=O,Ze=Ie}Un("setSize"),_e=!1}sn>0&&gn>0&&(h.clearRect(0,0,u.width,u.height),Un("drawClear"),E.forEach(y=>y()),Un("draw")),Kt.show&&ie&&(Wl(Kt),ie=!1),me&&te&&(Es(null,!0,!1),te=!1),fe.show&&fe.live&&pe&&(gf(),pe=!1),l||(l=!0,i.status=1,Un("ready")),$r=!1,an=!1}i.redraw=(y,M)=>{xe=M||!1,y!==!1?jr(A,P.min,P.max):Yn()};function df(y,M){let C=v[y];if(C.from==null){if(on==0){let L=C.range(i,M.min,M.max,y);M.min=L[0],M.max=L[1]}if(M.min>M.max){let L=M.min;M.min=M.max,M.max=L}if(on>1&&M.min!=null&&M.max!=null&&M.max-M.min<1e-16)return;y==A&&C.distr==2&&on>0&&(M.min=Xi(M.min,e[0]),M.max=Xi(M.max,e[0]),M.min==M.max&&M.max++),W[y]=M,oe=!0,Yn()}}i.setScale=df;let pf,mf,Js,js,Ym,Zm,Qs,eo,Km,$m,Zt,en,Jr=!1,zn=he.drag,Dn=zn.x,Fn=zn.y;me&&(he.x&&(pf=Ni(iw,p)),he.y&&(mf=Ni(rw,p)),P.ori==0?(Js=pf,js=mf):(Js=mf,js=pf),Zt=he.left,en=he.top);let Kt=i.select=Sn({show:!0,over:!0,left:0,width:0,top:0,height:0},n.select),to=Kt.show?Ni(nw,Kt.over?p:d):null;function Wl(y,M){if(Kt.show){for(let C in y)Kt[C]=y[C],C in yf&&qt(to,C,y[C]);M!==!1&&Un("setSelect")}}i.setSelect=Wl;function dS(y){if(b[y].show)ee&&Ud(ot[y],Cs);else if(ee&&_i(ot[y],Cs),me){let C=Re?lt[0]:lt[y];C!=null&&dr(C,-10,-10,O,Ie)}}function jr(y,M,C){df(y,{min:M,max:C})}function or(y,M,C,L){M.focus!=null&&yS(y),M.show!=null&&b.forEach((G,q)=>{q>0&&(y==q||y==null)&&(G.show=M.show,dS(q),r==2?(jr(G.facets[0].scale,null,null),jr(G.facets[1].scale,null,null)):jr(G.scale,null,null),Yn())}),C!==!1&&Un("setSeries",y,M),L&&va("setSeries",i,y,M)}i.setSeries=or;function pS(y,M){Sn(R[y],M)}function mS(y,M){y.fill=vt(y.fill||null),y.dir=Rt(y.dir,-1),M=M??R.length,R.splice(M,0,y)}function gS(y){y==null?R.length=0:R.splice(y,1)}i.addBand=mS,i.setBand=pS,i.delBand=gS;function _S(y,M){b[y].alpha=M,me&&lt[y]!=null&&(lt[y].style.opacity=M),ee&&ot[y]&&(ot[y].style.opacity=M)}let Tr,Qr,Ss,no={focus:!0};function yS(y){if(y!=Ss){let M=y==null,C=Be.alpha!=1;b.forEach((L,G)=>{if(r==1||G>0){let q=M||G==0||G==y;L._focus=M?null:q,C&&_S(G,q?1:Be.alpha)}}),Ss=y,C&&Yn()}}ee&&Qe&&wt(j_,Ae,y=>{he._lock||(je(y),Ss!=null&&or(null,no,!0,bn.setSeries))});function ar(y,M,C){let L=v[M];C&&(y=y/Ct-(L.ori==1?at:qe));let G=O;L.ori==1&&(G=Ie,y=G-y),L.dir==-1&&(y=G-y);let q=L._min,ae=L._max,de=y/G,be=q+(ae-q)*de,Le=L.distr;return Le==3?yo(10,be):Le==4?vw(be,L.asinh):Le==100?L.bwd(be):be}function xS(y,M){let C=ar(y,A,M);return Xi(C,e[0],fn,dn)}i.valToIdx=y=>Xi(y,e[0]),i.posToIdx=xS,i.posToVal=ar,i.valToPos=(y,M,C)=>v[M].ori==0?s(y,v[M],C?Y:O,C?I:0):o(y,v[M],C?ue:Ie,C?S:0),i.setCursor=(y,M,C)=>{Zt=y.left,en=y.top,Es(null,M,C)};function qm(y,M){qt(to,mo,Kt.left=y),qt(to,Ba,Kt.width=M)}function Jm(y,M){qt(to,"top",Kt.top=y),qt(to,ka,Kt.height=M)}let ya=P.ori==0?qm:Jm,xa=P.ori==1?qm:Jm;function bS(){if(ee&&fe.live)for(let y=r==2?1:0;y<b.length;y++){if(y==0&&ct)continue;let M=fe.values[y],C=0;for(let L in M)ze[y][C++].firstChild.nodeValue=M[L]}}function gf(y,M){if(y!=null&&(y.idxs?y.idxs.forEach((C,L)=>{re[L]=C}):ww(y.idx)||re.fill(y.idx),fe.idx=re[0]),ee&&fe.live){for(let C=0;C<b.length;C++)(C>0||r==1&&!ct)&&vS(C,re[C]);bS()}pe=!1,M!==!1&&Un("setLegend")}i.setLegend=gf;function vS(y,M){let C=b[y],L=y==0&&k==2?hi:e[y],G;ct?G=C.values(i,y,M)??rt:(G=C.value(i,M==null?null:L[M],y,M),G=G==null?rt:{_:G}),fe.values[y]=G}function Es(y,M,C){Km=Zt,$m=en,[Zt,en]=he.move(i,Zt,en),he.left=Zt,he.top=en,me&&(Js&&dr(Js,An(Zt),0,O,Ie),js&&dr(js,0,An(en),O,Ie));let L,G=fn>dn;Tr=zt,Qr=null;let q=P.ori==0?O:Ie,ae=P.ori==1?O:Ie;if(Zt<0||on==0||G){L=he.idx=null;for(let de=0;de<b.length;de++){let be=lt[de];be!=null&&dr(be,-10,-10,O,Ie)}Qe&&or(null,no,!0,y==null&&bn.setSeries),fe.live&&(re.fill(L),pe=!0)}else{let de,be,Le;r==1&&(de=P.ori==0?Zt:en,be=ar(de,A),L=he.idx=Xi(be,e[0],fn,dn),Le=H(e[0][L],P,q,0));let De=-10,Ue=-10,st=0,It=0,At=!0,yt="",Je="";for(let Ye=r==2?1:0;Ye<b.length;Ye++){let $t=b[Ye],ln=re[Ye],On=ln==null?null:r==1?e[Ye][ln]:e[Ye][1][ln],Bt=he.dataIdx(i,Ye,L,be),cn=Bt==null?null:r==1?e[Ye][Bt]:e[Ye][1][Bt];if(pe=pe||cn!=On||Bt!=ln,re[Ye]=Bt,Ye>0&&$t.show){let fi=Bt==null?-10:Bt==L?Le:H(r==1?e[0][Bt]:e[Ye][0][Bt],P,q,0),Qn=cn==null?-10:D(cn,r==1?v[$t.scale]:v[$t.facets[1].scale],ae,0);if(Qe&&cn!=null){let Ri=P.ori==1?Zt:en,ki=Rn(Be.dist(i,Ye,Bt,Qn,Ri));if(ki<Tr){let lr=Be.bias;if(lr!=0){let di=ar(Ri,$t.scale),Ii=cn>=0?1:-1,Vi=di>=0?1:-1;Vi==Ii&&(Vi==1?lr==1?cn>=di:cn<=di:lr==1?cn<=di:cn>=di)&&(Tr=ki,Qr=Ye)}else Tr=ki,Qr=Ye}}if(pe||Re){let Ri,ki;P.ori==0?(Ri=fi,ki=Qn):(Ri=Qn,ki=fi);let lr,di,Ii,Vi,cr,ei,pi=!0,Ms=le.bbox;if(Ms!=null){pi=!1;let ti=Ms(i,Ye);Ii=ti.left,Vi=ti.top,lr=ti.width,di=ti.height}else Ii=Ri,Vi=ki,lr=di=le.size(i,Ye);if(ei=le.fill(i,Ye),cr=le.stroke(i,Ye),Re)Ye==Qr&&Tr<=Be.prox&&(De=Ii,Ue=Vi,st=lr,It=di,At=pi,yt=ei,Je=cr);else{let ti=lt[Ye];ti!=null&&(Yt[Ye]=Ii,Jn[Ye]=Vi,sy(ti,lr,di,pi),iy(ti,ei,cr),dr(ti,Pi(Ii),Pi(Vi),O,Ie))}}}}if(Re){let Ye=Be.prox,$t=Ss==null?Tr<=Ye:Tr>Ye||Qr!=Ss;if(pe||$t){let ln=lt[0];ln!=null&&(Yt[0]=De,Jn[0]=Ue,sy(ln,st,It,At),iy(ln,yt,Je),dr(ln,Pi(De),Pi(Ue),O,Ie))}}}if(Kt.show&&Jr)if(y!=null){let[de,be]=bn.scales,[Le,De]=bn.match,[Ue,st]=y.cursor.sync.scales,It=y.cursor.drag;if(Dn=It._x,Fn=It._y,Dn||Fn){let{left:At,top:yt,width:Je,height:Ye}=y.select,$t=y.scales[Ue].ori,ln=y.posToVal,On,Bt,cn,fi,Qn,Ri=de!=null&&Le(de,Ue),ki=be!=null&&De(be,st);Ri&&Dn?($t==0?(On=At,Bt=Je):(On=yt,Bt=Ye),cn=v[de],fi=H(ln(On,Ue),cn,q,0),Qn=H(ln(On+Bt,Ue),cn,q,0),ya(Yi(fi,Qn),Rn(Qn-fi))):ya(0,q),ki&&Fn?($t==1?(On=At,Bt=Je):(On=yt,Bt=Ye),cn=v[be],fi=D(ln(On,st),cn,ae,0),Qn=D(ln(On+Bt,st),cn,ae,0),xa(Yi(fi,Qn),Rn(Qn-fi))):xa(0,ae)}else xf()}else{let de=Rn(Km-Ym),be=Rn($m-Zm);if(P.ori==1){let st=de;de=be,be=st}Dn=zn.x&&de>=zn.dist,Fn=zn.y&&be>=zn.dist;let Le=zn.uni;Le!=null?Dn&&Fn&&(Dn=de>=Le,Fn=be>=Le,!Dn&&!Fn&&(be>de?Fn=!0:Dn=!0)):zn.x&&zn.y&&(Dn||Fn)&&(Dn=Fn=!0);let De,Ue;Dn&&(P.ori==0?(De=Qs,Ue=Zt):(De=eo,Ue=en),ya(Yi(De,Ue),Rn(Ue-De)),Fn||xa(0,ae)),Fn&&(P.ori==1?(De=Qs,Ue=Zt):(De=eo,Ue=en),xa(Yi(De,Ue),Rn(Ue-De)),Dn||ya(0,q)),!Dn&&!Fn&&(ya(0,0),xa(0,0))}if(zn._x=Dn,zn._y=Fn,y==null){if(C){if(lg!=null){let[de,be]=bn.scales;bn.values[0]=de!=null?ar(P.ori==0?Zt:en,de):null,bn.values[1]=be!=null?ar(P.ori==1?Zt:en,be):null}va(Rd,i,Zt,en,O,Ie,L)}if(Qe){let de=C&&bn.setSeries,be=Be.prox;Ss==null?Tr<=be&&or(Qr,no,!0,de):Tr>be?or(null,no,!0,de):Qr!=Ss&&or(Qr,no,!0,de)}}pe&&(fe.idx=L,gf()),M!==!1&&Un("setCursor")}let es=null;Object.defineProperty(i,"rect",{get(){return es==null&&ba(!1),es}});function ba(y=!1){y?es=null:(es=p.getBoundingClientRect(),Un("syncRect",es))}function jm(y,M,C,L,G,q,ae){he._lock||Jr&&y!=null&&y.movementX==0&&y.movementY==0||(_f(y,M,C,L,G,q,ae,!1,y!=null),y!=null?Es(null,!0,!0):Es(M,!0,!1))}function _f(y,M,C,L,G,q,ae,de,be){if(es==null&&ba(!1),je(y),y!=null)C=y.clientX-es.left,L=y.clientY-es.top;else{if(C<0||L<0){Zt=-10,en=-10;return}let[Le,De]=bn.scales,Ue=M.cursor.sync,[st,It]=Ue.values,[At,yt]=Ue.scales,[Je,Ye]=bn.match,$t=M.axes[0].side%2==1,ln=P.ori==0?O:Ie,On=P.ori==1?O:Ie,Bt=$t?q:G,cn=$t?G:q,fi=$t?L:C,Qn=$t?C:L;if(At!=null?C=Je(Le,At)?a(st,v[Le],ln,0):-10:C=ln*(fi/Bt),yt!=null?L=Ye(De,yt)?a(It,v[De],On,0):-10:L=On*(Qn/cn),P.ori==1){let Ri=C;C=L,L=Ri}}be&&(M==null||M.cursor.event.type==Rd)&&((C<=1||C>=O-1)&&(C=Rs(C,O)),(L<=1||L>=Ie-1)&&(L=Rs(L,Ie))),de?(Ym=C,Zm=L,[Qs,eo]=he.move(i,C,L)):(Zt=C,en=L)}let yf={width:0,height:0,left:0,top:0};function xf(){Wl(yf,!1)}let Qm,eg,tg,ng;function ig(y,M,C,L,G,q,ae){Jr=!0,Dn=Fn=zn._x=zn._y=!1,_f(y,M,C,L,G,q,ae,!0,!1),y!=null&&(wt(Id,Dd,rg,!1),va(q_,i,Qs,eo,O,Ie,null));let{left:de,top:be,width:Le,height:De}=Kt;Qm=de,eg=be,tg=Le,ng=De}function rg(y,M,C,L,G,q,ae){Jr=zn._x=zn._y=!1,_f(y,M,C,L,G,q,ae,!1,!0);let{left:de,top:be,width:Le,height:De}=Kt,Ue=Le>0||De>0,st=Qm!=de||eg!=be||tg!=Le||ng!=De;if(Ue&&st&&Wl(Kt),zn.setScale&&Ue&&st){let It=de,At=Le,yt=be,Je=De;if(P.ori==1&&(It=be,At=De,yt=de,Je=Le),Dn&&jr(A,ar(It,A),ar(It+At,A)),Fn)for(let Ye in v){let $t=v[Ye];Ye!=A&&$t.from==null&&$t.min!=zt&&jr(Ye,ar(yt+Je,Ye),ar(yt,Ye))}xf()}else he.lock&&(he._lock=!he._lock,Es(M,!0,y!=null));y!=null&&(Mn(Id,Dd),va(Id,i,Zt,en,O,Ie,null))}function SS(y,M,C,L,G,q,ae){if(he._lock)return;je(y);let de=Jr;if(Jr){let be=!0,Le=!0,De=10,Ue,st;P.ori==0?(Ue=Dn,st=Fn):(Ue=Fn,st=Dn),Ue&&st&&(be=Zt<=De||Zt>=O-De,Le=en<=De||en>=Ie-De),Ue&&be&&(Zt=Zt<Qs?0:O),st&&Le&&(en=en<eo?0:Ie),Es(null,!0,!0),Jr=!1}Zt=-10,en=-10,re.fill(null),Es(null,!0,!0),de&&(Jr=de)}function sg(y,M,C,L,G,q,ae){he._lock||(je(y),_a(),xf(),y!=null&&va(Q_,i,Zt,en,O,Ie,null))}function og(){T.forEach(GT),U(i.width,i.height,!0)}Ns(Pc,_o,og);let io={};io.mousedown=ig,io.mousemove=jm,io.mouseup=rg,io.dblclick=sg,io.setSeries=(y,M,C,L)=>{let G=bn.match[2];C=G(i,M,C),C!=-1&&or(C,L,!0,!1)},me&&(wt(q_,p,ig),wt(Rd,p,jm),wt(J_,p,y=>{je(y),ba(!1)}),wt(j_,p,SS),wt(Q_,p,sg),zd.add(i),i.syncRect=ba);let Xl=i.hooks=n.hooks||{};function Un(y,M,C){jn?Ut.push([y,M,C]):y in Xl&&Xl[y].forEach(L=>{L.call(null,i,M,C)})}(n.plugins||[]).forEach(y=>{for(let M in y.hooks)Xl[M]=(Xl[M]||[]).concat(y.hooks[M])});let ag=(y,M,C)=>C,bn=Sn({key:null,setSeries:!1,filters:{pub:uy,sub:uy},scales:[A,b[1]?b[1].scale:null],match:[hy,hy,ag],values:[null,null]},he.sync);bn.match.length==2&&bn.match.push(ag),he.sync=bn;let lg=bn.key,bf=ax(lg);function va(y,M,C,L,G,q,ae){bn.filters.pub(y,M,C,L,G,q,ae)&&bf.pub(y,M,C,L,G,q,ae)}bf.sub(i);function ES(y,M,C,L,G,q,ae){bn.filters.sub(y,M,C,L,G,q,ae)&&io[y](null,M,C,L,G,q,ae)}i.pub=ES;function MS(){bf.unsub(i),zd.delete(i),Ln.clear(),Od(Pc,_o,og),c.remove(),Ae?.remove(),Un("destroy")}i.destroy=MS;function vf(){Un("init",n,e),ga(e||n.data,!1),W[A]?df(A,W[A]):_a(),ie=Kt.show&&(Kt.width>0||Kt.height>0),te=pe=!0,U(n.width,n.height)}return b.forEach(Zs),T.forEach(Sr),t?t instanceof HTMLElement?(t.appendChild(c),vf()):t(i,vf):vf(),i}Wn.assign=Sn;Wn.fmtNum=$d;Wn.rangeNum=Lc;Wn.rangeLog=Uc;Wn.rangeAsinh=Zd;Wn.orient=Ls;Wn.pxRatio=Ct;Wn.join=Pw;Wn.fmtDate=Jd,Wn.tzDate=Hw;Wn.sync=ax;{Wn.addGap=wT,Wn.clipGaps=kc;let n=Wn.paths={points:dx};n.linear=mx,n.stepped=RT,n.bars=IT,n.spline=NT}var zT=600,rp=class{t=[];ys;constructor(e){this.ys=Array.from({length:e},()=>[])}push(e,t){if(this.t.push(e),t.forEach((i,r)=>this.ys[r].push(i===null||!Number.isFinite(i)?null:i)),this.t.length>zT){this.t.shift();for(let i of this.ys)i.shift()}}clear(){this.t.length=0;for(let e of this.ys)e.length=0}},rs=class{constructor(e,t,i,r,s){this.title=t;this.series=r;this.ring=new rp(r.length);let o=document.createElement("div");o.className="chart",e.appendChild(o),this.plot=new Wn({title:t,width:s,height:84,legend:{show:!0,live:!1},cursor:{show:!1},scales:{x:{time:!1}},axes:[{stroke:"#9aa5b1",grid:{stroke:"#26303a"},size:30,label:"simulated time (s)",labelSize:12,labelFont:"11px system-ui"},{stroke:"#9aa5b1",grid:{stroke:"#26303a"},size:52,label:i,labelSize:14}],series:[{label:"t (s)"},...r.map(a=>({label:a.label,stroke:a.stroke,dash:a.dash,width:1.5,spanGaps:!1}))]},[[],...r.map(()=>[])],o),this.note=document.createElement("p"),this.note.className="plot-note",o.appendChild(this.note)}title;series;plot;ring;note;setNote(e){this.note.textContent!==e&&(this.note.textContent=e)}redraw(){this.plot.setData([this.ring.t,...this.ring.ys])}counts(){return this.series.map((e,t)=>({label:e.label,values:this.ring.ys[t].filter(i=>i!==null).length}))}get noteText(){return this.note.textContent??""}},HT=[["integrate","#74c0fc"],["broad","#ffd43b"],["prioritise","#b197fc"],["narrow","#ff8787"],["response","#63e6be"],["measure","#ced4da"]],Hc=class{charts;constructor(e,t){this.charts=[new rs(e,"T, collision time","ms",[{label:"T",stroke:"#4dabf7"}],t),new rs(e,"\u0394, geometric inaccuracy","scene units",[{label:"\u0394",stroke:"#ffa94d"}],t),new rs(e,"P, perceived inaccuracy","unitless",[{label:"P estimate",stroke:"#ff6b6b"},{label:"P true (audit)",stroke:"#e599f7",dash:[4,3]},{label:"P true, gaze-blind",stroke:"#74c0fc",dash:[2,2]}],t),new rs(e,"budget","%",[{label:"budget used",stroke:"#69db7c"},{label:"pairs deemed",stroke:"#ff4d4d"}],t),new rs(e,"step phases","ms",HT.map(([i,r])=>({label:i,stroke:r})),t),new rs(e,"frame rate","fps",[{label:"frames received",stroke:"#ced4da"}],t)]}push(e){let[t,i,r,s,o,a]=this.charts;t.ring.push(e.t,[e.collisionMs]),i.ring.push(e.t,[e.geometric]),r.ring.push(e.t,[e.perceived,e.truePerceived,e.blindTruePerceived]),s.ring.push(e.t,[e.budgetUse===null?null:100*e.budgetUse,e.deemedShare===null?null:100*e.deemedShare]),o.ring.push(e.t,e.phasesMs),a.ring.push(e.t,[e.fps])}setNotes(e){this.charts[2].setNote(e.perceived),this.charts[3].setNote(e.budget)}clear(){for(let e of this.charts)e.ring.clear()}redraw(){for(let e of this.charts)e.redraw()}summary(){return this.charts.map(e=>({title:e.title,series:e.counts(),note:e.noteText}))}};var Wa=600,WT=["frame","sim_time_s","collision_time_ms","geometric_inaccuracy_units","perceived_inaccuracy","perceived_inaccuracy_se","true_perceived_inaccuracy","true_false_positives","candidate_pairs","real_collisions","deemed_at_interruption","sphere_tests","budget_exhausted","metrics_stride","integrate_ms","broad_ms","prioritise_ms","narrow_ms","response_ms","measure_ms","renumber_ms","fixation_x","fixation_y","fixation_source"],XT={1:"gaze",2:"fallback_no_gaze",3:"fallback_stale",4:"fallback_track_lost"},Wc=class{rows=[];indices=[];push(e){let t=e.metrics,i=e.profile,r=e.fixation;if(!t)return;let s=a=>a===void 0?"":String(1e3*a),o=[String(e.index),String(e.simTimeS),s(t.collisionTimeS),String(t.geometricInaccuracy),String(t.perceivedInaccuracy),String(t.perceivedInaccuracySe),t.audit?String(t.audit.truePerceivedInaccuracy):"",t.audit?String(t.audit.trueFalsePositives):"",String(t.candidatePairs),String(t.realCollisions),String(t.deemedAtInterruption),String(t.sphereTests),t.budgetExhausted?"1":"0",String(t.metricsStride),s(i?.integrateS),s(i?.broadS),s(i?.prioritiseS),s(i?.narrowS),s(i?.responseS),s(i?.measureS),s(i?.renumberS),r?String(r.x):"",r?String(r.y):"",r?XT[r.source]??"unspecified":""];this.rows.push(o.join(",")),this.indices.push(Number(e.index)),this.rows.length>Wa&&(this.rows.shift(),this.indices.shift())}clear(){this.rows.length=0,this.indices.length=0}csv(e=Wa){let t=this.rows.slice(-Math.max(1,Math.min(e,Wa)));return[WT.join(","),...t].join(`
`)+`
`}range(e=Wa){let t=this.indices.slice(-Math.max(1,Math.min(e,Wa)));return t.length?`${t[0]}-${t[t.length-1]}`:"none"}};function xx(n,e,t){if(e.part===0){let a=Math.sin(e.u);t[0]=n.coreRadius*a*Math.cos(e.v),t[1]=n.coreRadius*a*Math.sin(e.v),t[2]=n.coreRadius*Math.cos(e.u);return}let i=e.part-1>>1,r=e.part-1&1?-1:1,s=Math.min(1,Math.max(0,e.u)),o=n.spikeBaseRadius*(1-s);t[i]=r*s*n.radius,t[(i+1)%3]=o*Math.cos(e.v),t[(i+2)%3]=o*Math.sin(e.v)}function bx(n,e,t,i){let r=i*e[t],s=e[(t+1)%3],o=e[(t+2)%3],a=Math.sqrt(s*s+o*o),l=n.radius,c=n.spikeBaseRadius,u=Math.max(0,a-c),h=Math.sqrt(r*r+u*u),f=Math.min(1,Math.max(0,(r*l-(a-c)*c)/(l*l+c*c))),d=r-f*l,p=a-c+f*c,x=Math.sqrt(d*d+p*p);return r>=0&&a<=c*(1-r/l)?-Math.min(h,x):Math.min(h,x)}function YT(n,e){let t=Math.sqrt(e[0]*e[0]+e[1]*e[1]+e[2]*e[2])-n.coreRadius;for(let i=0;i<3;i++)t=Math.min(t,bx(n,e,i,1),bx(n,e,i,-1));return t}function vx(n,e,t){let i=n.m,r=n.o;for(let s=0;s<3;s++)t[s]=i[r+s]*e[0]+i[r+4+s]*e[1]+i[r+8+s]*e[2]+i[r+12+s]}function ZT(n,e,t){let i=n.m,r=n.o,s=e[0]-i[r+12],o=e[1]-i[r+13],a=e[2]-i[r+14];for(let l=0;l<3;l++)t[l]=i[r+4*l]*s+i[r+4*l+1]*o+i[r+4*l+2]*a}function KT(){let n=[];for(let e=0;e<=12;e++)for(let t=0;t<24;t++)n.push({part:0,u:Math.PI*e/12,v:2*Math.PI*t/24});for(let e=1;e<=6;e++){for(let t=0;t<32;t++)for(let i=0;i<24;i++)n.push({part:e,u:t/32,v:2*Math.PI*i/24});n.push({part:e,u:1,v:0})}return n}var Sx=KT();function Ex(n,e,t){let i=[0,0,0],r=[0,0,0],s=[0,0,0],o=f=>(xx(n,f,i),vx(e,i,r),ZT(t,r,s),YT(n,s)),a=Sx[0],l=1/0;for(let f of Sx){let d=o(f);d<l&&(l=d,a=f)}let c={...a},u=c.part===0?Math.PI/12:1/32,h=2*Math.PI/24;for(let f=0;f<40;f++){let d=!1;for(let[p,x]of[[1,0],[-1,0],[0,1],[0,-1]]){let m={part:c.part,u:c.u+p*u,v:c.v+x*h};m.part!==0&&(m.u=Math.min(1,Math.max(0,m.u)));let g=o(m);g<l&&(l=g,c=m,d=!0)}d||(u/=2,h/=2)}return xx(n,c,i),vx(e,i,r),{d:l,at:[...r]}}function Mx(n,e,t){let i=Ex(n,e,t),r=Ex(n,t,e);return{gap:Math.min(i.d,r.d),ends:[i.at,r.at]}}var Xc=class{last=-1;lastTime=-1;before=new Set;reset(){this.last=-1,this.lastTime=-1,this.before.clear()}next(e,t,i){let r=this.last>=0&&e===this.last+1&&t>this.lastTime,s=new Set,o=[];for(let[a,l]of i){let c=Math.min(a,l),u=Math.max(a,l),h=`${c},${u}`;s.add(h),r&&!this.before.has(h)&&o.push([c,u])}return this.before=s,this.last=e,this.lastTime=t,o}};var wx=Math.SQRT1_2;function Tx(n,e,t,i,r,s,o,a,l){let c=t+t,u=i+i,h=r+r,f=t*c,d=t*u,p=t*h,x=i*u,m=i*h,g=r*h,b=s*c,T=s*u,v=s*h;n[e]=1-(x+g),n[e+1]=d+v,n[e+2]=p-T,n[e+3]=0,n[e+4]=d-v,n[e+5]=1-(f+g),n[e+6]=m+b,n[e+7]=0,n[e+8]=p+T,n[e+9]=m-b,n[e+10]=1-(f+x),n[e+11]=0,n[e+12]=o,n[e+13]=a,n[e+14]=l,n[e+15]=1}function wo(n){return new DataView(n.buffer,n.byteOffset,n.byteLength)}function Ax(n,e){let t=Math.min(n.bodies,n.positions.length/6,n.orientations.length/4,e.length/16)|0,i=wo(n.positions),r=wo(n.orientations),s=n.origin?.x??0,o=n.origin?.y??0,a=n.origin?.z??0,l=n.extent/65535,c=2/1023*wx,u=new Float32Array(4);for(let h=0;h<t;h++){let f=s+i.getUint16(6*h,!0)*l,d=o+i.getUint16(6*h+2,!0)*l,p=a+i.getUint16(6*h+4,!0)*l,x=r.getUint32(4*h,!0),m=x>>>30,g=20,b=0;for(let T=0;T<4;T++){if(T===m)continue;let v=(x>>>g&1023)*c-wx;u[T]=v,b+=v*v,g-=10}u[m]=Math.sqrt(Math.max(0,1-b)),Tx(e,16*h,u[0],u[1],u[2],u[3],f,d,p)}return t}function Rx(n,e){let t=Math.min(n.bodies,n.positions.length/12,n.orientations.length/16,e.length/16)|0,i=wo(n.positions),r=wo(n.orientations),s=n.origin?.x??0,o=n.origin?.y??0,a=n.origin?.z??0;for(let l=0;l<t;l++)Tx(e,16*l,r.getFloat32(16*l,!0),r.getFloat32(16*l+4,!0),r.getFloat32(16*l+8,!0),r.getFloat32(16*l+12,!0),s+i.getFloat32(12*l,!0),o+i.getFloat32(12*l+4,!0),a+i.getFloat32(12*l+8,!0));return t}function Yc(n,e){let t=wo(n);for(let i=0;i+8<=n.length;i+=8)e(t.getUint32(i,!0),t.getUint32(i+4,!0))}function sp(n,e){let t=wo(n.deemed),i=n.deemedTruth;for(let r=0,s=0;r+8<=n.deemed.length;r+=8,s++)e(t.getUint32(r,!0),t.getUint32(r+4,!0),i[s]??0)}function Ix(){try{new Headers}catch{throw new Error("connect-web requires the fetch API. Are you running on an old version of Node.js? Node.js is not supported in Connect for Web - please stay tuned for Connect for Node.")}}function Xa(n,e){let t=vc(n);if(t)throw e.forEach((i,r)=>{t.metadata.append(r,i)}),t;if(!e.has(Hi)&&!n.has(Hi))throw new dt("protocol error: missing status",We.Internal)}function Zc(n,e,t,i){var r,s;let o=new Headers(t??{});o.set(md,n?E_:M_),o.set(S_,"1");let a=(s=(r=o.get(bc))!==null&&r!==void 0?r:o.get(yd))!==null&&s!==void 0?s:"connect-es/2.1.2";return o.set(yd,a),i&&o.set(bc,a),e!==void 0&&o.set(gd,`${e}m`),o}function Cx(n){switch(n){case 400:return We.Internal;case 401:return We.Unauthenticated;case 403:return We.PermissionDenied;case 404:return We.Unimplemented;case 429:return We.Unavailable;case 502:return We.Unavailable;case 503:return We.Unavailable;case 504:return We.Unavailable;default:return We.Unknown}}function Kc(n,e){var t;if(n>=200&&n<300)return{foundStatus:e.has(Hi),headerError:vc(e)};throw new dt(decodeURIComponent((t=e.get(Da))!==null&&t!==void 0?t:`HTTP ${n}`),Cx(n),e)}var Ds=function(n){return this instanceof Ds?(this.v=n,this):new Ds(n)},$T=function(n,e,t){if(!Symbol.asyncIterator)throw new TypeError("Symbol.asyncIterator is not defined.");var i=t.apply(n,e||[]),r,s=[];return r=Object.create((typeof AsyncIterator=="function"?AsyncIterator:Object).prototype),a("next"),a("throw"),a("return",o),r[Symbol.asyncIterator]=function(){return this},r;function o(d){return function(p){return Promise.resolve(p).then(d,h)}}function a(d,p){i[d]&&(r[d]=function(x){return new Promise(function(m,g){s.push([d,x,m,g])>1||l(d,x)})},p&&(r[d]=p(r[d])))}function l(d,p){try{c(i[d](p))}catch(x){f(s[0][3],x)}}function c(d){d.value instanceof Ds?Promise.resolve(d.value.v).then(u,h):f(s[0][2],d)}function u(d){l("next",d)}function h(d){l("throw",d)}function f(d,p){d(p),s.shift(),s.length&&l(s[0][0],s[0][1])}},Nx={redirect:"error"};function op(n){var e;Ix();let t=(e=n.useBinaryFormat)!==null&&e!==void 0?e:!0;return{async unary(i,r,s,o,a,l){let{serialize:c,parse:u}=Ec(i,t,n.jsonOptions,n.binaryOptions);return s=s===void 0?n.defaultTimeoutMs:s<=0?void 0:s,await vd({interceptors:n.interceptors,signal:r,timeoutMs:s,req:{stream:!1,service:i.parent,method:i,requestMethod:"POST",url:Sc(n.baseUrl,i),header:Zc(t,s,o,!1),contextValues:l??yc(),message:a},next:async h=>{var f;let p=await((f=n.fetch)!==null&&f!==void 0?f:globalThis.fetch)(h.url,Object.assign(Object.assign({},Nx),{method:h.requestMethod,headers:h.header,signal:h.signal,body:_c(0,c(h.message))})),{headerError:x}=Kc(p.status,p.headers);if(!p.body)throw x!==void 0?x:"missing response body";let m=gc(p.body).getReader(),g,b;for(;;){let T=await m.read();if(T.done)break;let{flags:v,data:R}=T.value;if((v&mc)===mc)throw new dt("protocol error: received unsupported compressed output",We.Internal);if(v===128){if(g!==void 0)throw"extra trailer";g=xc(R);continue}if(b!==void 0)throw new dt("extra message",We.Unimplemented);b=u(R)}if(g===void 0)throw x!==void 0?x:new dt("missing trailer",p.headers.has(Hi)?We.Unimplemented:We.Unknown);if(Xa(g,p.headers),b===void 0)throw new dt("missing message",g.has(Hi)?We.Unimplemented:We.Unknown);return{stream:!1,service:i.parent,method:i,header:p.headers,message:b,trailer:g}}})},async stream(i,r,s,o,a,l){let{serialize:c,parse:u}=Ec(i,t,n.jsonOptions,n.binaryOptions);function h(d,p,x,m,g){return $T(this,arguments,function*(){let T=gc(d).getReader();if(p){if(!(yield Ds(T.read())).done)throw"extra data for trailers-only";return yield Ds(void 0)}let v=!1;for(;;){let R=yield Ds(T.read());if(R.done)break;let{flags:A,data:_}=R.value;if((A&128)===128){if(v)throw"extra trailer";v=!0;let E=xc(_);Xa(E,m),E.forEach((F,N)=>x.set(N,F));continue}if(v)throw"extra message";yield yield Ds(u(_))}if("throwIfAborted"in g&&g.throwIfAborted(),!v)throw"missing trailer"})}async function f(d){if(i.methodKind!="server_streaming")throw"The fetch API does not support streaming request bodies";let p=await d[Symbol.asyncIterator]().next();if(p.done==!0)throw"missing request message";return _c(0,c(p.value))}return s=s===void 0?n.defaultTimeoutMs:s<=0?void 0:s,Sd({interceptors:n.interceptors,signal:r,timeoutMs:s,req:{stream:!0,service:i.parent,method:i,requestMethod:"POST",url:Sc(n.baseUrl,i),header:Zc(t,s,o,!1),contextValues:l??yc(),message:a},next:async d=>{var p;let m=await((p=n.fetch)!==null&&p!==void 0?p:globalThis.fetch)(d.url,Object.assign(Object.assign({},Nx),{method:d.requestMethod,headers:d.header,signal:d.signal,body:await f(d.message)})),{foundStatus:g,headerError:b}=Kc(m.status,m.headers);if(b!=null)throw b;if(!m.body)throw"missing response body";let T=new Headers;return Object.assign(Object.assign({},d),{header:m.headers,trailer:T,message:h(m.body,g,T,m.headers,d.signal)})}})}}}var qT="foveal.token",JT="foveal.gaze-token";function Px(){let n=new URLSearchParams(window.location.hash.slice(1)),e=(i,r)=>{let s=n.get(i);return s&&sessionStorage.setItem(r,s),s||sessionStorage.getItem(r)},t={token:e("token",qT),gazeToken:e("gaze",JT)};if(n.has("token")||n.has("gaze")){n.delete("token"),n.delete("gaze");let i=[...n].map(([r,s])=>s?`${encodeURIComponent(r)}=${encodeURIComponent(s)}`:encodeURIComponent(r)).join("&");history.replaceState(history.state,"",`${window.location.pathname}${window.location.search}${i?`#${i}`:""}`)}return t}var ap={started:0};function lp(n,e){return dd(V_,op({baseUrl:n,useBinaryFormat:!0,interceptors:[i=>async r=>(ap.started++,e&&r.header.set("authorization",`Bearer ${e}`),i(r))]}))}var _s={LEFT:0,MIDDLE:1,RIGHT:2,ROTATE:0,DOLLY:1,PAN:2},ys={ROTATE:0,PAN:1,DOLLY_PAN:2,DOLLY_ROTATE:3},hb=0,kp=1,fb=2;var Tl=1,db=2,Qo=3,xs=0,si=1,yr=2,Gs=0,ea=1,Vp=2,Gp=3,zp=4,pb=5;var zs=100,mb=101,gb=102,_b=103,yb=104,xb=200,bb=201,vb=202,Sb=203,Hp=204,Wp=205,Eb=206,Mb=207,wb=208,Tb=209,Ab=210,Rb=211,Ib=212,Cb=213,Nb=214,Mu=0,wu=1,Tu=2,zo=3,Au=4,Ru=5,Iu=6,Cu=7,sh=0,Pb=1,Lb=2,xr=0,Xp=1,Yp=2,Zp=3,Kp=4,$p=5,qp=6,Jp=7;var jp=300,Hs=301,ta=302,oh=303,ah=304,Nu=1e3,mr=1001,Pu=1002,Vn=1003,Db=1004;var Al=1005;var ri=1006,lh=1007;var Hr=1008;var li=1009,Qp=1010,em=1011,na=1012,ch=1013,ji=1014,Ui=1015,Qi=1016,uh=1017,hh=1018,Ws=1020,tm=35902,nm=35899,im=1021,rm=1022,er=1023,kr=1026,Wr=1027,fh=1028,dh=1029,bs=1030,ph=1031;var mh=1033,Rl=33776,Il=33777,Cl=33778,Nl=33779,gh=35840,_h=35841,yh=35842,xh=35843,bh=36196,vh=37492,Sh=37496,Eh=37488,Mh=37489,Pl=37490,wh=37491,Th=37808,Ah=37809,Rh=37810,Ih=37811,Ch=37812,Nh=37813,Ph=37814,Lh=37815,Dh=37816,Fh=37817,Uh=37818,Oh=37819,Bh=37820,kh=37821,Vh=36492,Gh=36494,zh=36495,Hh=36283,Wh=36284,Ll=36285,Xh=36286;var tl=2300,Lu=2301,Su=2302,Np=2303,Pp=2400,Lp=2401,Dp=2402;var Fb=3200;var Yh=0,Ub=1,Xr="",Si="srgb",nl="srgb-linear",il="linear",Lt="srgb";var Eu=7680;var Ob=519,Bb=512,kb=513,Vb=514,sm=515,Gb=516,zb=517,om=518,am=519,Hb=35044,ia=35048;var lm="300 es",Di=2e3,Ho=2001;function jT(n){for(let e=n.length-1;e>=0;--e)if(n[e]>=65535)return!0;return!1}function QT(n){return ArrayBuffer.isView(n)&&!(n instanceof DataView)}function rl(n){return document.createElementNS("http://www.w3.org/1999/xhtml",n)}function Wb(){let n=rl("canvas");return n.style.display="block",n}var Lx={},Wo=null;function cm(...n){let e="THREE."+n.shift();Wo?Wo("log",e,...n):console.log(e,...n)}function Xb(n){let e=n[0];if(typeof e=="string"&&e.startsWith("TSL:")){let t=n[1];t&&t.isStackTrace?n[0]+=" "+t.getLocation():n[1]='Stack trace not available. Enable "THREE.Node.captureStackTrace" to capture stack traces.'}return n}function $e(...n){n=Xb(n);let e="THREE."+n.shift();if(Wo)Wo("warn",e,...n);else{let t=n[0];t&&t.isStackTrace?console.warn(t.getError(e)):console.warn(e,...n)}}function et(...n){n=Xb(n);let e="THREE."+n.shift();if(Wo)Wo("error",e,...n);else{let t=n[0];t&&t.isStackTrace?console.error(t.getError(e)):console.error(e,...n)}}function Qa(...n){let e=n.join(" ");e in Lx||(Lx[e]=!0,$e(...n))}function Yb(n,e,t){return new Promise(function(i,r){function s(){switch(n.clientWaitSync(e,n.SYNC_FLUSH_COMMANDS_BIT,0)){case n.WAIT_FAILED:r();break;case n.TIMEOUT_EXPIRED:setTimeout(s,t);break;default:i()}}setTimeout(s,t)})}var Zb={[Mu]:Mu,[Tu]:Iu,[Au]:Au,[zo]:Ru,[wu]:wu,[Iu]:Tu,[Cu]:Cu,[Ru]:zo},qi=class{addEventListener(e,t){this._listeners===void 0&&(this._listeners={});let i=this._listeners;i[e]===void 0&&(i[e]=[]),i[e].indexOf(t)===-1&&i[e].push(t)}hasEventListener(e,t){let i=this._listeners;return i===void 0?!1:i[e]!==void 0&&i[e].indexOf(t)!==-1}removeEventListener(e,t){let i=this._listeners;if(i===void 0)return;let r=i[e];if(r!==void 0){let s=r.indexOf(t);s!==-1&&r.splice(s,1)}}dispatchEvent(e){let t=this._listeners;if(t===void 0)return;let i=t[e.type];if(i!==void 0){e.target=this;let r=i.slice(0);for(let s=0,o=r.length;s<o;s++)r[s].call(this,e);e.target=null}}},Kn=["00","01","02","03","04","05","06","07","08","09","0a","0b","0c","0d","0e","0f","10","11","12","13","14","15","16","17","18","19","1a","1b","1c","1d","1e","1f","20","21","22","23","24","25","26","27","28","29","2a","2b","2c","2d","2e","2f","30","31","32","33","34","35","36","37","38","39","3a","3b","3c","3d","3e","3f","40","41","42","43","44","45","46","47","48","49","4a","4b","4c","4d","4e","4f","50","51","52","53","54","55","56","57","58","59","5a","5b","5c","5d","5e","5f","60","61","62","63","64","65","66","67","68","69","6a","6b","6c","6d","6e","6f","70","71","72","73","74","75","76","77","78","79","7a","7b","7c","7d","7e","7f","80","81","82","83","84","85","86","87","88","89","8a","8b","8c","8d","8e","8f","90","91","92","93","94","95","96","97","98","99","9a","9b","9c","9d","9e","9f","a0","a1","a2","a3","a4","a5","a6","a7","a8","a9","aa","ab","ac","ad","ae","af","b0","b1","b2","b3","b4","b5","b6","b7","b8","b9","ba","bb","bc","bd","be","bf","c0","c1","c2","c3","c4","c5","c6","c7","c8","c9","ca","cb","cc","cd","ce","cf","d0","d1","d2","d3","d4","d5","d6","d7","d8","d9","da","db","dc","dd","de","df","e0","e1","e2","e3","e4","e5","e6","e7","e8","e9","ea","eb","ec","ed","ee","ef","f0","f1","f2","f3","f4","f5","f6","f7","f8","f9","fa","fb","fc","fd","fe","ff"],Dx=1234567,Vo=Math.PI/180,Xo=180/Math.PI;function ra(){let n=Math.random()*4294967295|0,e=Math.random()*4294967295|0,t=Math.random()*4294967295|0,i=Math.random()*4294967295|0;return(Kn[n&255]+Kn[n>>8&255]+Kn[n>>16&255]+Kn[n>>24&255]+"-"+Kn[e&255]+Kn[e>>8&255]+"-"+Kn[e>>16&15|64]+Kn[e>>24&255]+"-"+Kn[t&63|128]+Kn[t>>8&255]+"-"+Kn[t>>16&255]+Kn[t>>24&255]+Kn[i&255]+Kn[i>>8&255]+Kn[i>>16&255]+Kn[i>>24&255]).toLowerCase()}function _t(n,e,t){return Math.max(e,Math.min(t,n))}function um(n,e){return(n%e+e)%e}function eA(n,e,t,i,r){return i+(n-e)*(r-i)/(t-e)}function tA(n,e,t){return n!==e?(t-n)/(e-n):0}function el(n,e,t){return(1-t)*n+t*e}function nA(n,e,t,i){return el(n,e,1-Math.exp(-t*i))}function iA(n,e=1){return e-Math.abs(um(n,e*2)-e)}function rA(n,e,t){return n<=e?0:n>=t?1:(n=(n-e)/(t-e),n*n*(3-2*n))}function sA(n,e,t){return n<=e?0:n>=t?1:(n=(n-e)/(t-e),n*n*n*(n*(n*6-15)+10))}function oA(n,e){return n+Math.floor(Math.random()*(e-n+1))}function aA(n,e){return n+Math.random()*(e-n)}function lA(n){return n*(.5-Math.random())}function cA(n){n!==void 0&&(Dx=n);let e=Dx+=1831565813;return e=Math.imul(e^e>>>15,e|1),e^=e+Math.imul(e^e>>>7,e|61),((e^e>>>14)>>>0)/4294967296}function uA(n){return n*Vo}function hA(n){return n*Xo}function fA(n){return n>0&&Number.isInteger(n)&&2**Math.round(Math.log2(n))===n}function dA(n){return Math.pow(2,Math.ceil(Math.log(n)/Math.LN2))}function hm(n){return Math.pow(2,Math.floor(Math.log(n)/Math.LN2))}function pA(n,e,t,i,r){let s=Math.cos,o=Math.sin,a=s(t/2),l=o(t/2),c=s((e+i)/2),u=o((e+i)/2),h=s((e-i)/2),f=o((e-i)/2),d=s((i-e)/2),p=o((i-e)/2);switch(r){case"XYX":n.set(a*u,l*h,l*f,a*c);break;case"YZY":n.set(l*f,a*u,l*h,a*c);break;case"ZXZ":n.set(l*h,l*f,a*u,a*c);break;case"XZX":n.set(a*u,l*p,l*d,a*c);break;case"YXY":n.set(l*d,a*u,l*p,a*c);break;case"ZYZ":n.set(l*p,l*d,a*u,a*c);break;default:$e("MathUtils: .setQuaternionFromProperEuler() encountered an unknown order: "+r)}}function fm(n){switch(n.constructor){case Uint32Array:return 4294967295;case Uint16Array:return 65535;case Uint8Array:case Uint8ClampedArray:return 255;case Int32Array:return 2147483647;case Int16Array:return 32767;case Int8Array:return 127;default:return}}function Kb(n,e){if(e.constructor===Float32Array)return n;let t=fm(e);if(t===void 0)throw new Error("THREE.MathUtils: Invalid component type.");return Math.max(n/t,-1)}function $b(n,e){if(e.constructor===Float32Array)return n;let t=fm(e);if(t===void 0)throw new Error("THREE.MathUtils: Invalid component type.");return Math.round(n*t)}var sa={DEG2RAD:Vo,RAD2DEG:Xo,generateUUID:ra,clamp:_t,euclideanModulo:um,mapLinear:eA,inverseLerp:tA,lerp:el,damp:nA,pingpong:iA,smoothstep:rA,smootherstep:sA,randInt:oA,randFloat:aA,randFloatSpread:lA,seededRandom:cA,degToRad:uA,radToDeg:hA,isPowerOfTwo:fA,ceilPowerOfTwo:dA,floorPowerOfTwo:hm,setQuaternionFromProperEuler:pA,normalize:$b,denormalize:Kb},Ke=class{static{this.prototype.isVector2=!0}constructor(e=0,t=0){this.x=e,this.y=t}get width(){return this.x}set width(e){this.x=e}get height(){return this.y}set height(e){this.y=e}set(e,t){return this.x=e,this.y=t,this}setScalar(e){return this.x=e,this.y=e,this}setX(e){return this.x=e,this}setY(e){return this.y=e,this}setComponent(e,t){switch(e){case 0:this.x=t;break;case 1:this.y=t;break;default:throw new Error("THREE.Vector2: index is out of range: "+e)}return this}getComponent(e){switch(e){case 0:return this.x;case 1:return this.y;default:throw new Error("THREE.Vector2: index is out of range: "+e)}}clone(){return new this.constructor(this.x,this.y)}copy(e){return this.x=e.x,this.y=e.y,this}add(e){return this.x+=e.x,this.y+=e.y,this}addScalar(e){return this.x+=e,this.y+=e,this}addVectors(e,t){return this.x=e.x+t.x,this.y=e.y+t.y,this}addScaledVector(e,t){return this.x+=e.x*t,this.y+=e.y*t,this}sub(e){return this.x-=e.x,this.y-=e.y,this}subScalar(e){return this.x-=e,this.y-=e,this}subVectors(e,t){return this.x=e.x-t.x,this.y=e.y-t.y,this}multiply(e){return this.x*=e.x,this.y*=e.y,this}multiplyScalar(e){return this.x*=e,this.y*=e,this}divide(e){return this.x/=e.x,this.y/=e.y,this}divideScalar(e){return this.multiplyScalar(1/e)}applyMatrix3(e){let t=this.x,i=this.y,r=e.elements;return this.x=r[0]*t+r[3]*i+r[6],this.y=r[1]*t+r[4]*i+r[7],this}min(e){return this.x=Math.min(this.x,e.x),this.y=Math.min(this.y,e.y),this}max(e){return this.x=Math.max(this.x,e.x),this.y=Math.max(this.y,e.y),this}clamp(e,t){return this.x=_t(this.x,e.x,t.x),this.y=_t(this.y,e.y,t.y),this}clampScalar(e,t){return this.x=_t(this.x,e,t),this.y=_t(this.y,e,t),this}clampLength(e,t){let i=this.length();return this.divideScalar(i||1).multiplyScalar(_t(i,e,t))}floor(){return this.x=Math.floor(this.x),this.y=Math.floor(this.y),this}ceil(){return this.x=Math.ceil(this.x),this.y=Math.ceil(this.y),this}round(){return this.x=Math.round(this.x),this.y=Math.round(this.y),this}roundToZero(){return this.x=Math.trunc(this.x),this.y=Math.trunc(this.y),this}negate(){return this.x=-this.x,this.y=-this.y,this}dot(e){return this.x*e.x+this.y*e.y}cross(e){return this.x*e.y-this.y*e.x}lengthSq(){return this.x*this.x+this.y*this.y}length(){return Math.sqrt(this.x*this.x+this.y*this.y)}manhattanLength(){return Math.abs(this.x)+Math.abs(this.y)}normalize(){return this.divideScalar(this.length()||1)}angle(){return Math.atan2(-this.y,-this.x)+Math.PI}angleTo(e){let t=Math.sqrt(this.lengthSq()*e.lengthSq());if(t===0)return Math.PI/2;let i=this.dot(e)/t;return Math.acos(_t(i,-1,1))}distanceTo(e){return Math.sqrt(this.distanceToSquared(e))}distanceToSquared(e){let t=this.x-e.x,i=this.y-e.y;return t*t+i*i}manhattanDistanceTo(e){return Math.abs(this.x-e.x)+Math.abs(this.y-e.y)}setLength(e){return this.normalize().multiplyScalar(e)}lerp(e,t){return this.x+=(e.x-this.x)*t,this.y+=(e.y-this.y)*t,this}lerpVectors(e,t,i){return this.x=e.x+(t.x-e.x)*i,this.y=e.y+(t.y-e.y)*i,this}equals(e){return e.x===this.x&&e.y===this.y}fromArray(e,t=0){return this.x=e[t],this.y=e[t+1],this}toArray(e=[],t=0){return e[t]=this.x,e[t+1]=this.y,e}fromBufferAttribute(e,t){return this.x=e.getX(t),this.y=e.getY(t),this}rotateAround(e,t){let i=Math.cos(t),r=Math.sin(t),s=this.x-e.x,o=this.y-e.y;return this.x=s*i-o*r+e.x,this.y=s*r+o*i+e.y,this}random(){return this.x=Math.random(),this.y=Math.random(),this}*[Symbol.iterator](){yield this.x,yield this.y}},Mi=class{constructor(e=0,t=0,i=0,r=1){this.isQuaternion=!0,this._x=e,this._y=t,this._z=i,this._w=r}static slerpFlat(e,t,i,r,s,o,a){let l=i[r+0],c=i[r+1],u=i[r+2],h=i[r+3],f=s[o+0],d=s[o+1],p=s[o+2],x=s[o+3];if(h!==x||l!==f||c!==d||u!==p){let m=l*f+c*d+u*p+h*x;m<0&&(f=-f,d=-d,p=-p,x=-x,m=-m);let g=1-a;if(m<.9995){let b=Math.acos(m),T=Math.sin(b);g=Math.sin(g*b)/T,a=Math.sin(a*b)/T,l=l*g+f*a,c=c*g+d*a,u=u*g+p*a,h=h*g+x*a}else{l=l*g+f*a,c=c*g+d*a,u=u*g+p*a,h=h*g+x*a;let b=1/Math.sqrt(l*l+c*c+u*u+h*h);l*=b,c*=b,u*=b,h*=b}}e[t]=l,e[t+1]=c,e[t+2]=u,e[t+3]=h}static multiplyQuaternionsFlat(e,t,i,r,s,o){let a=i[r],l=i[r+1],c=i[r+2],u=i[r+3],h=s[o],f=s[o+1],d=s[o+2],p=s[o+3];return e[t]=a*p+u*h+l*d-c*f,e[t+1]=l*p+u*f+c*h-a*d,e[t+2]=c*p+u*d+a*f-l*h,e[t+3]=u*p-a*h-l*f-c*d,e}get x(){return this._x}set x(e){this._x=e,this._onChangeCallback()}get y(){return this._y}set y(e){this._y=e,this._onChangeCallback()}get z(){return this._z}set z(e){this._z=e,this._onChangeCallback()}get w(){return this._w}set w(e){this._w=e,this._onChangeCallback()}set(e,t,i,r){return this._x=e,this._y=t,this._z=i,this._w=r,this._onChangeCallback(),this}clone(){return new this.constructor(this._x,this._y,this._z,this._w)}copy(e){return this._x=e.x,this._y=e.y,this._z=e.z,this._w=e.w,this._onChangeCallback(),this}setFromEuler(e,t=!0){let i=e._x,r=e._y,s=e._z,o=e._order,a=Math.cos,l=Math.sin,c=a(i/2),u=a(r/2),h=a(s/2),f=l(i/2),d=l(r/2),p=l(s/2);switch(o){case"XYZ":this._x=f*u*h+c*d*p,this._y=c*d*h-f*u*p,this._z=c*u*p+f*d*h,this._w=c*u*h-f*d*p;break;case"YXZ":this._x=f*u*h+c*d*p,this._y=c*d*h-f*u*p,this._z=c*u*p-f*d*h,this._w=c*u*h+f*d*p;break;case"ZXY":this._x=f*u*h-c*d*p,this._y=c*d*h+f*u*p,this._z=c*u*p+f*d*h,this._w=c*u*h-f*d*p;break;case"ZYX":this._x=f*u*h-c*d*p,this._y=c*d*h+f*u*p,this._z=c*u*p-f*d*h,this._w=c*u*h+f*d*p;break;case"YZX":this._x=f*u*h+c*d*p,this._y=c*d*h+f*u*p,this._z=c*u*p-f*d*h,this._w=c*u*h-f*d*p;break;case"XZY":this._x=f*u*h-c*d*p,this._y=c*d*h-f*u*p,this._z=c*u*p+f*d*h,this._w=c*u*h+f*d*p;break;default:$e("Quaternion: .setFromEuler() encountered an unknown order: "+o)}return t===!0&&this._onChangeCallback(),this}setFromAxisAngle(e,t){let i=t/2,r=Math.sin(i);return this._x=e.x*r,this._y=e.y*r,this._z=e.z*r,this._w=Math.cos(i),this._onChangeCallback(),this}setFromRotationMatrix(e){let t=e.elements,i=t[0],r=t[4],s=t[8],o=t[1],a=t[5],l=t[9],c=t[2],u=t[6],h=t[10],f=i+a+h;if(f>0){let d=.5/Math.sqrt(f+1);this._w=.25/d,this._x=(u-l)*d,this._y=(s-c)*d,this._z=(o-r)*d}else if(i>a&&i>h){let d=2*Math.sqrt(1+i-a-h);this._w=(u-l)/d,this._x=.25*d,this._y=(r+o)/d,this._z=(s+c)/d}else if(a>h){let d=2*Math.sqrt(1+a-i-h);this._w=(s-c)/d,this._x=(r+o)/d,this._y=.25*d,this._z=(l+u)/d}else{let d=2*Math.sqrt(1+h-i-a);this._w=(o-r)/d,this._x=(s+c)/d,this._y=(l+u)/d,this._z=.25*d}return this._onChangeCallback(),this}setFromUnitVectors(e,t){let i=e.dot(t)+1;return i<1e-8?(i=0,Math.abs(e.x)>Math.abs(e.z)?(this._x=-e.y,this._y=e.x,this._z=0,this._w=i):(this._x=0,this._y=-e.z,this._z=e.y,this._w=i)):(this._x=e.y*t.z-e.z*t.y,this._y=e.z*t.x-e.x*t.z,this._z=e.x*t.y-e.y*t.x,this._w=i),this.normalize()}angleTo(e){return 2*Math.acos(Math.abs(_t(this.dot(e),-1,1)))}rotateTowards(e,t){let i=this.angleTo(e);if(i===0)return this;let r=Math.min(1,t/i);return this.slerp(e,r),this}identity(){return this.set(0,0,0,1)}invert(){return this.conjugate()}conjugate(){return this._x*=-1,this._y*=-1,this._z*=-1,this._onChangeCallback(),this}dot(e){return this._x*e._x+this._y*e._y+this._z*e._z+this._w*e._w}lengthSq(){return this._x*this._x+this._y*this._y+this._z*this._z+this._w*this._w}length(){return Math.sqrt(this._x*this._x+this._y*this._y+this._z*this._z+this._w*this._w)}normalize(){let e=this.length();return e===0?(this._x=0,this._y=0,this._z=0,this._w=1):(e=1/e,this._x=this._x*e,this._y=this._y*e,this._z=this._z*e,this._w=this._w*e),this._onChangeCallback(),this}multiply(e){return this.multiplyQuaternions(this,e)}premultiply(e){return this.multiplyQuaternions(e,this)}multiplyQuaternions(e,t){let i=e._x,r=e._y,s=e._z,o=e._w,a=t._x,l=t._y,c=t._z,u=t._w;return this._x=i*u+o*a+r*c-s*l,this._y=r*u+o*l+s*a-i*c,this._z=s*u+o*c+i*l-r*a,this._w=o*u-i*a-r*l-s*c,this._onChangeCallback(),this}slerp(e,t){let i=e._x,r=e._y,s=e._z,o=e._w,a=this.dot(e);a<0&&(i=-i,r=-r,s=-s,o=-o,a=-a);let l=1-t;if(a<.9995){let c=Math.acos(a),u=Math.sin(c);l=Math.sin(l*c)/u,t=Math.sin(t*c)/u,this._x=this._x*l+i*t,this._y=this._y*l+r*t,this._z=this._z*l+s*t,this._w=this._w*l+o*t,this._onChangeCallback()}else this._x=this._x*l+i*t,this._y=this._y*l+r*t,this._z=this._z*l+s*t,this._w=this._w*l+o*t,this.normalize();return this}slerpQuaternions(e,t,i){return this.copy(e).slerp(t,i)}random(){let e=2*Math.PI*Math.random(),t=2*Math.PI*Math.random(),i=Math.random(),r=Math.sqrt(1-i),s=Math.sqrt(i);return this.set(r*Math.sin(e),r*Math.cos(e),s*Math.sin(t),s*Math.cos(t))}equals(e){return e._x===this._x&&e._y===this._y&&e._z===this._z&&e._w===this._w}fromArray(e,t=0){return this._x=e[t],this._y=e[t+1],this._z=e[t+2],this._w=e[t+3],this._onChangeCallback(),this}toArray(e=[],t=0){return e[t]=this._x,e[t+1]=this._y,e[t+2]=this._z,e[t+3]=this._w,e}fromBufferAttribute(e,t){return this._x=e.getX(t),this._y=e.getY(t),this._z=e.getZ(t),this._w=e.getW(t),this._onChangeCallback(),this}toJSON(){return this.toArray()}_onChange(e){return this._onChangeCallback=e,this}_onChangeCallback(){}*[Symbol.iterator](){yield this._x,yield this._y,yield this._z,yield this._w}},X=class{static{this.prototype.isVector3=!0}constructor(e=0,t=0,i=0){this.x=e,this.y=t,this.z=i}set(e,t,i){return i===void 0&&(i=this.z),this.x=e,this.y=t,this.z=i,this}setScalar(e){return this.x=e,this.y=e,this.z=e,this}setX(e){return this.x=e,this}setY(e){return this.y=e,this}setZ(e){return this.z=e,this}setComponent(e,t){switch(e){case 0:this.x=t;break;case 1:this.y=t;break;case 2:this.z=t;break;default:throw new Error("THREE.Vector3: index is out of range: "+e)}return this}getComponent(e){switch(e){case 0:return this.x;case 1:return this.y;case 2:return this.z;default:throw new Error("THREE.Vector3: index is out of range: "+e)}}clone(){return new this.constructor(this.x,this.y,this.z)}copy(e){return this.x=e.x,this.y=e.y,this.z=e.z,this}add(e){return this.x+=e.x,this.y+=e.y,this.z+=e.z,this}addScalar(e){return this.x+=e,this.y+=e,this.z+=e,this}addVectors(e,t){return this.x=e.x+t.x,this.y=e.y+t.y,this.z=e.z+t.z,this}addScaledVector(e,t){return this.x+=e.x*t,this.y+=e.y*t,this.z+=e.z*t,this}sub(e){return this.x-=e.x,this.y-=e.y,this.z-=e.z,this}subScalar(e){return this.x-=e,this.y-=e,this.z-=e,this}subVectors(e,t){return this.x=e.x-t.x,this.y=e.y-t.y,this.z=e.z-t.z,this}multiply(e){return this.x*=e.x,this.y*=e.y,this.z*=e.z,this}multiplyScalar(e){return this.x*=e,this.y*=e,this.z*=e,this}multiplyVectors(e,t){return this.x=e.x*t.x,this.y=e.y*t.y,this.z=e.z*t.z,this}applyEuler(e){return this.applyQuaternion(Fx.setFromEuler(e))}applyAxisAngle(e,t){return this.applyQuaternion(Fx.setFromAxisAngle(e,t))}applyMatrix3(e){let t=this.x,i=this.y,r=this.z,s=e.elements;return this.x=s[0]*t+s[3]*i+s[6]*r,this.y=s[1]*t+s[4]*i+s[7]*r,this.z=s[2]*t+s[5]*i+s[8]*r,this}applyNormalMatrix(e){return this.applyMatrix3(e).normalize()}applyMatrix4(e){let t=this.x,i=this.y,r=this.z,s=e.elements,o=1/(s[3]*t+s[7]*i+s[11]*r+s[15]);return this.x=(s[0]*t+s[4]*i+s[8]*r+s[12])*o,this.y=(s[1]*t+s[5]*i+s[9]*r+s[13])*o,this.z=(s[2]*t+s[6]*i+s[10]*r+s[14])*o,this}applyQuaternion(e){let t=this.x,i=this.y,r=this.z,s=e.x,o=e.y,a=e.z,l=e.w,c=2*(o*r-a*i),u=2*(a*t-s*r),h=2*(s*i-o*t);return this.x=t+l*c+o*h-a*u,this.y=i+l*u+a*c-s*h,this.z=r+l*h+s*u-o*c,this}project(e){return this.applyMatrix4(e.matrixWorldInverse).applyMatrix4(e.projectionMatrix)}unproject(e){return this.applyMatrix4(e.projectionMatrixInverse).applyMatrix4(e.matrixWorld)}transformDirection(e){let t=this.x,i=this.y,r=this.z,s=e.elements;return this.x=s[0]*t+s[4]*i+s[8]*r,this.y=s[1]*t+s[5]*i+s[9]*r,this.z=s[2]*t+s[6]*i+s[10]*r,this.normalize()}divide(e){return this.x/=e.x,this.y/=e.y,this.z/=e.z,this}divideScalar(e){return this.multiplyScalar(1/e)}min(e){return this.x=Math.min(this.x,e.x),this.y=Math.min(this.y,e.y),this.z=Math.min(this.z,e.z),this}max(e){return this.x=Math.max(this.x,e.x),this.y=Math.max(this.y,e.y),this.z=Math.max(this.z,e.z),this}clamp(e,t){return this.x=_t(this.x,e.x,t.x),this.y=_t(this.y,e.y,t.y),this.z=_t(this.z,e.z,t.z),this}clampScalar(e,t){return this.x=_t(this.x,e,t),this.y=_t(this.y,e,t),this.z=_t(this.z,e,t),this}clampLength(e,t){let i=this.length();return this.divideScalar(i||1).multiplyScalar(_t(i,e,t))}floor(){return this.x=Math.floor(this.x),this.y=Math.floor(this.y),this.z=Math.floor(this.z),this}ceil(){return this.x=Math.ceil(this.x),this.y=Math.ceil(this.y),this.z=Math.ceil(this.z),this}round(){return this.x=Math.round(this.x),this.y=Math.round(this.y),this.z=Math.round(this.z),this}roundToZero(){return this.x=Math.trunc(this.x),this.y=Math.trunc(this.y),this.z=Math.trunc(this.z),this}negate(){return this.x=-this.x,this.y=-this.y,this.z=-this.z,this}dot(e){return this.x*e.x+this.y*e.y+this.z*e.z}lengthSq(){return this.x*this.x+this.y*this.y+this.z*this.z}length(){return Math.sqrt(this.x*this.x+this.y*this.y+this.z*this.z)}manhattanLength(){return Math.abs(this.x)+Math.abs(this.y)+Math.abs(this.z)}normalize(){return this.divideScalar(this.length()||1)}setLength(e){return this.normalize().multiplyScalar(e)}lerp(e,t){return this.x+=(e.x-this.x)*t,this.y+=(e.y-this.y)*t,this.z+=(e.z-this.z)*t,this}lerpVectors(e,t,i){return this.x=e.x+(t.x-e.x)*i,this.y=e.y+(t.y-e.y)*i,this.z=e.z+(t.z-e.z)*i,this}cross(e){return this.crossVectors(this,e)}crossVectors(e,t){let i=e.x,r=e.y,s=e.z,o=t.x,a=t.y,l=t.z;return this.x=r*l-s*a,this.y=s*o-i*l,this.z=i*a-r*o,this}projectOnVector(e){let t=e.lengthSq();if(t===0)return this.set(0,0,0);let i=e.dot(this)/t;return this.copy(e).multiplyScalar(i)}projectOnPlane(e){return cp.copy(this).projectOnVector(e),this.sub(cp)}reflect(e){return this.sub(cp.copy(e).multiplyScalar(2*this.dot(e)))}angleTo(e){let t=Math.sqrt(this.lengthSq()*e.lengthSq());if(t===0)return Math.PI/2;let i=this.dot(e)/t;return Math.acos(_t(i,-1,1))}distanceTo(e){return Math.sqrt(this.distanceToSquared(e))}distanceToSquared(e){let t=this.x-e.x,i=this.y-e.y,r=this.z-e.z;return t*t+i*i+r*r}manhattanDistanceTo(e){return Math.abs(this.x-e.x)+Math.abs(this.y-e.y)+Math.abs(this.z-e.z)}setFromSpherical(e){return this.setFromSphericalCoords(e.radius,e.phi,e.theta)}setFromSphericalCoords(e,t,i){let r=Math.sin(t)*e;return this.x=r*Math.sin(i),this.y=Math.cos(t)*e,this.z=r*Math.cos(i),this}setFromCylindrical(e){return this.setFromCylindricalCoords(e.radius,e.theta,e.y)}setFromCylindricalCoords(e,t,i){return this.x=e*Math.sin(t),this.y=i,this.z=e*Math.cos(t),this}setFromMatrixPosition(e){let t=e.elements;return this.x=t[12],this.y=t[13],this.z=t[14],this}setFromMatrixScale(e){let t=this.setFromMatrixColumn(e,0).length(),i=this.setFromMatrixColumn(e,1).length(),r=this.setFromMatrixColumn(e,2).length();return this.x=t,this.y=i,this.z=r,this}setFromMatrixColumn(e,t){return this.fromArray(e.elements,t*4)}setFromMatrix3Column(e,t){return this.fromArray(e.elements,t*3)}setFromEuler(e){return this.x=e._x,this.y=e._y,this.z=e._z,this}setFromColor(e){return this.x=e.r,this.y=e.g,this.z=e.b,this}equals(e){return e.x===this.x&&e.y===this.y&&e.z===this.z}fromArray(e,t=0){return this.x=e[t],this.y=e[t+1],this.z=e[t+2],this}toArray(e=[],t=0){return e[t]=this.x,e[t+1]=this.y,e[t+2]=this.z,e}fromBufferAttribute(e,t){return this.x=e.getX(t),this.y=e.getY(t),this.z=e.getZ(t),this}random(){return this.x=Math.random(),this.y=Math.random(),this.z=Math.random(),this}randomDirection(){let e=Math.random()*Math.PI*2,t=Math.random()*2-1,i=Math.sqrt(1-t*t);return this.x=i*Math.cos(e),this.y=t,this.z=i*Math.sin(e),this}*[Symbol.iterator](){yield this.x,yield this.y,yield this.z}},cp=new X,Fx=new Mi,it=class{static{this.prototype.isMatrix3=!0}constructor(e,t,i,r,s,o,a,l,c){this.elements=[1,0,0,0,1,0,0,0,1],e!==void 0&&this.set(e,t,i,r,s,o,a,l,c)}set(e,t,i,r,s,o,a,l,c){let u=this.elements;return u[0]=e,u[1]=r,u[2]=a,u[3]=t,u[4]=s,u[5]=l,u[6]=i,u[7]=o,u[8]=c,this}identity(){return this.set(1,0,0,0,1,0,0,0,1),this}copy(e){let t=this.elements,i=e.elements;return t[0]=i[0],t[1]=i[1],t[2]=i[2],t[3]=i[3],t[4]=i[4],t[5]=i[5],t[6]=i[6],t[7]=i[7],t[8]=i[8],this}extractBasis(e,t,i){return e.setFromMatrix3Column(this,0),t.setFromMatrix3Column(this,1),i.setFromMatrix3Column(this,2),this}setFromMatrix4(e){let t=e.elements;return this.set(t[0],t[4],t[8],t[1],t[5],t[9],t[2],t[6],t[10]),this}multiply(e){return this.multiplyMatrices(this,e)}premultiply(e){return this.multiplyMatrices(e,this)}multiplyMatrices(e,t){let i=e.elements,r=t.elements,s=this.elements,o=i[0],a=i[3],l=i[6],c=i[1],u=i[4],h=i[7],f=i[2],d=i[5],p=i[8],x=r[0],m=r[3],g=r[6],b=r[1],T=r[4],v=r[7],R=r[2],A=r[5],_=r[8];return s[0]=o*x+a*b+l*R,s[3]=o*m+a*T+l*A,s[6]=o*g+a*v+l*_,s[1]=c*x+u*b+h*R,s[4]=c*m+u*T+h*A,s[7]=c*g+u*v+h*_,s[2]=f*x+d*b+p*R,s[5]=f*m+d*T+p*A,s[8]=f*g+d*v+p*_,this}multiplyScalar(e){let t=this.elements;return t[0]*=e,t[3]*=e,t[6]*=e,t[1]*=e,t[4]*=e,t[7]*=e,t[2]*=e,t[5]*=e,t[8]*=e,this}determinant(){let e=this.elements,t=e[0],i=e[1],r=e[2],s=e[3],o=e[4],a=e[5],l=e[6],c=e[7],u=e[8];return t*o*u-t*a*c-i*s*u+i*a*l+r*s*c-r*o*l}invert(){let e=this.elements,t=e[0],i=e[1],r=e[2],s=e[3],o=e[4],a=e[5],l=e[6],c=e[7],u=e[8],h=u*o-a*c,f=a*l-u*s,d=c*s-o*l,p=t*h+i*f+r*d;if(p===0)return this.set(0,0,0,0,0,0,0,0,0);let x=1/p;return e[0]=h*x,e[1]=(r*c-u*i)*x,e[2]=(a*i-r*o)*x,e[3]=f*x,e[4]=(u*t-r*l)*x,e[5]=(r*s-a*t)*x,e[6]=d*x,e[7]=(i*l-c*t)*x,e[8]=(o*t-i*s)*x,this}transpose(){let e,t=this.elements;return e=t[1],t[1]=t[3],t[3]=e,e=t[2],t[2]=t[6],t[6]=e,e=t[5],t[5]=t[7],t[7]=e,this}getNormalMatrix(e){return this.setFromMatrix4(e).invert().transpose()}transposeIntoArray(e){let t=this.elements;return e[0]=t[0],e[1]=t[3],e[2]=t[6],e[3]=t[1],e[4]=t[4],e[5]=t[7],e[6]=t[2],e[7]=t[5],e[8]=t[8],this}setUvTransform(e,t,i,r,s,o,a){let l=Math.cos(s),c=Math.sin(s);return this.set(i*l,i*c,-i*(l*o+c*a)+o+e,-r*c,r*l,-r*(-c*o+l*a)+a+t,0,0,1),this}scale(e,t){return Qa("Matrix3: .scale() is deprecated. Use .makeScale() instead."),this.premultiply(up.makeScale(e,t)),this}rotate(e){return Qa("Matrix3: .rotate() is deprecated. Use .makeRotation() instead."),this.premultiply(up.makeRotation(-e)),this}translate(e,t){return Qa("Matrix3: .translate() is deprecated. Use .makeTranslation() instead."),this.premultiply(up.makeTranslation(e,t)),this}makeTranslation(e,t){return e.isVector2?this.set(1,0,e.x,0,1,e.y,0,0,1):this.set(1,0,e,0,1,t,0,0,1),this}makeRotation(e){let t=Math.cos(e),i=Math.sin(e);return this.set(t,-i,0,i,t,0,0,0,1),this}makeScale(e,t){return this.set(e,0,0,0,t,0,0,0,1),this}equals(e){let t=this.elements,i=e.elements;for(let r=0;r<9;r++)if(t[r]!==i[r])return!1;return!0}fromArray(e,t=0){for(let i=0;i<9;i++)this.elements[i]=e[i+t];return this}toArray(e=[],t=0){let i=this.elements;return e[t]=i[0],e[t+1]=i[1],e[t+2]=i[2],e[t+3]=i[3],e[t+4]=i[4],e[t+5]=i[5],e[t+6]=i[6],e[t+7]=i[7],e[t+8]=i[8],e}clone(){return new this.constructor().fromArray(this.elements)}},up=new it,Ux=new it().set(.4123908,.3575843,.1804808,.212639,.7151687,.0721923,.0193308,.1191948,.9505322),Ox=new it().set(3.2409699,-1.5373832,-.4986108,-.9692436,1.8759675,.0415551,.0556301,-.203977,1.0569715);function mA(){let n={enabled:!0,workingColorSpace:nl,spaces:{},convert:function(r,s,o){return this.enabled===!1||s===o||!s||!o||(this.spaces[s].transfer===Lt&&(r.r=Br(r.r),r.g=Br(r.g),r.b=Br(r.b)),this.spaces[s].primaries!==this.spaces[o].primaries&&(r.applyMatrix3(this.spaces[s].toXYZ),r.applyMatrix3(this.spaces[o].fromXYZ)),this.spaces[o].transfer===Lt&&(r.r=Go(r.r),r.g=Go(r.g),r.b=Go(r.b))),r},workingToColorSpace:function(r,s){return this.convert(r,this.workingColorSpace,s)},colorSpaceToWorking:function(r,s){return this.convert(r,s,this.workingColorSpace)},getPrimaries:function(r){return this.spaces[r].primaries},getTransfer:function(r){return r===Xr?il:this.spaces[r].transfer},getToneMappingMode:function(r){return this.spaces[r].outputColorSpaceConfig.toneMappingMode||"standard"},getLuminanceCoefficients:function(r,s=this.workingColorSpace){return r.fromArray(this.spaces[s].luminanceCoefficients)},define:function(r){Object.assign(this.spaces,r)},_getMatrix:function(r,s,o){return r.copy(this.spaces[o].fromXYZ).multiply(this.spaces[s].toXYZ)},_getDrawingBufferColorSpace:function(r){return this.spaces[r].outputColorSpaceConfig.drawingBufferColorSpace},_getUnpackColorSpace:function(r=this.workingColorSpace){return this.spaces[r].workingColorSpaceConfig.unpackColorSpace}},e=[.64,.33,.3,.6,.15,.06],t=[.2126,.7152,.0722],i=[.3127,.329];return n.define({[nl]:{primaries:e,whitePoint:i,transfer:il,toXYZ:Ux,fromXYZ:Ox,luminanceCoefficients:t,workingColorSpaceConfig:{unpackColorSpace:Si},outputColorSpaceConfig:{drawingBufferColorSpace:Si}},[Si]:{primaries:e,whitePoint:i,transfer:Lt,toXYZ:Ux,fromXYZ:Ox,luminanceCoefficients:t,outputColorSpaceConfig:{drawingBufferColorSpace:Si}}}),n}var St=mA();function Br(n){return n<.04045?n*.0773993808:Math.pow(n*.9478672986+.0521327014,2.4)}function Go(n){return n<.0031308?n*12.92:1.055*Math.pow(n,.41666)-.055}var To,Du=class{static getDataURL(e,t="image/png"){if(/^data:/i.test(e.src)||typeof HTMLCanvasElement>"u")return e.src;let i;if(e instanceof HTMLCanvasElement)i=e;else{To===void 0&&(To=rl("canvas")),To.width=e.width,To.height=e.height;let r=To.getContext("2d");e instanceof ImageData?r.putImageData(e,0,0):r.drawImage(e,0,0,e.width,e.height),i=To}return i.toDataURL(t)}static sRGBToLinear(e){if(typeof HTMLImageElement<"u"&&e instanceof HTMLImageElement||typeof HTMLCanvasElement<"u"&&e instanceof HTMLCanvasElement||typeof ImageBitmap<"u"&&e instanceof ImageBitmap){let t=rl("canvas");t.width=e.width,t.height=e.height;let i=t.getContext("2d");i.drawImage(e,0,0,e.width,e.height);let r=i.getImageData(0,0,e.width,e.height),s=r.data;for(let o=0;o<s.length;o++)s[o]=Br(s[o]/255)*255;return i.putImageData(r,0,0),t}else if(e.data){let t=e.data.slice(0);for(let i=0;i<t.length;i++)t instanceof Uint8Array||t instanceof Uint8ClampedArray?t[i]=Math.floor(Br(t[i]/255)*255):t[i]=Br(t[i]);return{data:t,width:e.width,height:e.height}}else return $e("ImageUtils.sRGBToLinear(): Unsupported image type. No color space conversion applied."),e}},gA=0,Yo=class{constructor(e=null){this.isTextureSource=!0,Object.defineProperty(this,"id",{value:gA++}),this.uuid=ra(),this.data=e,this.dataReady=!0,this.version=0}getSize(e){let t=this.data;return typeof HTMLVideoElement<"u"&&t instanceof HTMLVideoElement?e.set(t.videoWidth,t.videoHeight,0):typeof VideoFrame<"u"&&t instanceof VideoFrame?e.set(t.displayWidth,t.displayHeight,0):t!==null?e.set(t.width||0,t.height||0,t.depth||0):e.set(0,0,0),e}set needsUpdate(e){e===!0&&this.version++}toJSON(e){let t=e===void 0||typeof e=="string";if(!t&&e.images[this.uuid]!==void 0)return e.images[this.uuid];let i={uuid:this.uuid,url:""},r=this.data;if(r!==null){let s;if(Array.isArray(r)){s=[];for(let o=0,a=r.length;o<a;o++)r[o].isDataTexture?s.push(hp(r[o].image)):s.push(hp(r[o]))}else s=hp(r);i.url=s}return t||(e.images[this.uuid]=i),i}};function hp(n){return typeof HTMLImageElement<"u"&&n instanceof HTMLImageElement||typeof HTMLCanvasElement<"u"&&n instanceof HTMLCanvasElement||typeof ImageBitmap<"u"&&n instanceof ImageBitmap?Du.getDataURL(n):n.data?{data:Array.from(n.data),width:n.width,height:n.height,type:n.data.constructor.name}:($e("Texture: Unable to serialize Texture."),{})}var _A=0,fp=new X,ai=class n extends qi{constructor(e=n.DEFAULT_IMAGE,t=n.DEFAULT_MAPPING,i=mr,r=mr,s=ri,o=Hr,a=er,l=li,c=n.DEFAULT_ANISOTROPY,u=Xr){super(),this.isTexture=!0,Object.defineProperty(this,"id",{value:_A++}),this.uuid=ra(),this.name="",this.source=new Yo(e),this.mipmaps=[],this.mapping=t,this.channel=0,this.wrapS=i,this.wrapT=r,this.magFilter=s,this.minFilter=o,this.anisotropy=c,this.format=a,this.internalFormat=null,this.type=l,this.offset=new Ke(0,0),this.repeat=new Ke(1,1),this.center=new Ke(0,0),this.rotation=0,this.matrixAutoUpdate=!0,this.matrix=new it,this.generateMipmaps=!0,this.mipmapsAutoUpdate=!0,this.premultiplyAlpha=!1,this.flipY=!0,this.unpackAlignment=4,this.colorSpace=u,this.userData={},this.updateRanges=[],this.version=0,this.onUpdate=null,this.renderTarget=null,this.isRenderTargetTexture=!1,this.isArrayTexture=!!(e&&e.depth&&e.depth>1),this.pmremVersion=0,this.isPMREMTexture=!1,this.normalized=!1}get width(){return this.source.getSize(fp).x}get height(){return this.source.getSize(fp).y}get depth(){return this.source.getSize(fp).z}get image(){return this.source.data}set image(e){this.source.data=e}updateMatrix(){this.matrix.setUvTransform(this.offset.x,this.offset.y,this.repeat.x,this.repeat.y,this.rotation,this.center.x,this.center.y)}addUpdateRange(e,t){this.updateRanges.push({start:e,count:t})}clearUpdateRanges(){this.updateRanges.length=0}clone(){return new this.constructor().copy(this)}copy(e){return this.name=e.name,this.source=e.source,this.mipmaps=e.mipmaps.slice(0),this.mapping=e.mapping,this.channel=e.channel,this.wrapS=e.wrapS,this.wrapT=e.wrapT,this.magFilter=e.magFilter,this.minFilter=e.minFilter,this.anisotropy=e.anisotropy,this.format=e.format,this.internalFormat=e.internalFormat,this.type=e.type,this.normalized=e.normalized,this.offset.copy(e.offset),this.repeat.copy(e.repeat),this.center.copy(e.center),this.rotation=e.rotation,this.matrixAutoUpdate=e.matrixAutoUpdate,this.matrix.copy(e.matrix),this.generateMipmaps=e.generateMipmaps,this.mipmapsAutoUpdate=e.mipmapsAutoUpdate,this.premultiplyAlpha=e.premultiplyAlpha,this.flipY=e.flipY,this.unpackAlignment=e.unpackAlignment,this.colorSpace=e.colorSpace,this.renderTarget=e.renderTarget,this.isRenderTargetTexture=e.isRenderTargetTexture,this.isPMREMTexture=e.isPMREMTexture,this.isArrayTexture=e.isArrayTexture,this.userData=JSON.parse(JSON.stringify(e.userData)),this.needsUpdate=!0,this}setValues(e){for(let t in e){let i=e[t];if(i===void 0){$e(`Texture.setValues(): parameter '${t}' has value of undefined.`);continue}let r=this[t];if(r===void 0){$e(`Texture.setValues(): property '${t}' does not exist.`);continue}r&&i&&r.isVector2&&i.isVector2||r&&i&&r.isVector3&&i.isVector3||r&&i&&r.isMatrix3&&i.isMatrix3?r.copy(i):this[t]=i}}toJSON(e){let t=e===void 0||typeof e=="string";if(!t&&e.textures[this.uuid]!==void 0)return e.textures[this.uuid];let i={metadata:{version:4.7,type:"Texture",generator:"Texture.toJSON"},uuid:this.uuid,name:this.name,image:this.source.toJSON(e).uuid,mapping:this.mapping,channel:this.channel,repeat:[this.repeat.x,this.repeat.y],offset:[this.offset.x,this.offset.y],center:[this.center.x,this.center.y],rotation:this.rotation,wrap:[this.wrapS,this.wrapT],format:this.format,internalFormat:this.internalFormat,type:this.type,normalized:this.normalized,colorSpace:this.colorSpace,minFilter:this.minFilter,magFilter:this.magFilter,anisotropy:this.anisotropy,flipY:this.flipY,generateMipmaps:this.generateMipmaps,mipmapsAutoUpdate:this.mipmapsAutoUpdate,premultiplyAlpha:this.premultiplyAlpha,unpackAlignment:this.unpackAlignment};return Object.keys(this.userData).length>0&&(i.userData=this.userData),t||(e.textures[this.uuid]=i),i}dispose(){this.dispatchEvent({type:"dispose"})}transformUv(e){if(this.mapping!==jp)return e;if(e.applyMatrix3(this.matrix),e.x<0||e.x>1)switch(this.wrapS){case Nu:e.x=e.x-Math.floor(e.x);break;case mr:e.x=e.x<0?0:1;break;case Pu:Math.abs(Math.floor(e.x)%2)===1?e.x=Math.ceil(e.x)-e.x:e.x=e.x-Math.floor(e.x);break}if(e.y<0||e.y>1)switch(this.wrapT){case Nu:e.y=e.y-Math.floor(e.y);break;case mr:e.y=e.y<0?0:1;break;case Pu:Math.abs(Math.floor(e.y)%2)===1?e.y=Math.ceil(e.y)-e.y:e.y=e.y-Math.floor(e.y);break}return this.flipY&&(e.y=1-e.y),e}set needsUpdate(e){e===!0&&(this.version++,this.source.needsUpdate=!0)}set needsPMREMUpdate(e){e===!0&&this.pmremVersion++}};ai.DEFAULT_IMAGE=null;ai.DEFAULT_MAPPING=jp;ai.DEFAULT_ANISOTROPY=1;var tn=class{static{this.prototype.isVector4=!0}constructor(e=0,t=0,i=0,r=1){this.x=e,this.y=t,this.z=i,this.w=r}get width(){return this.z}set width(e){this.z=e}get height(){return this.w}set height(e){this.w=e}set(e,t,i,r){return this.x=e,this.y=t,this.z=i,this.w=r,this}setScalar(e){return this.x=e,this.y=e,this.z=e,this.w=e,this}setX(e){return this.x=e,this}setY(e){return this.y=e,this}setZ(e){return this.z=e,this}setW(e){return this.w=e,this}setComponent(e,t){switch(e){case 0:this.x=t;break;case 1:this.y=t;break;case 2:this.z=t;break;case 3:this.w=t;break;default:throw new Error("THREE.Vector4: index is out of range: "+e)}return this}getComponent(e){switch(e){case 0:return this.x;case 1:return this.y;case 2:return this.z;case 3:return this.w;default:throw new Error("THREE.Vector4: index is out of range: "+e)}}clone(){return new this.constructor(this.x,this.y,this.z,this.w)}copy(e){return this.x=e.x,this.y=e.y,this.z=e.z,this.w=e.w!==void 0?e.w:1,this}add(e){return this.x+=e.x,this.y+=e.y,this.z+=e.z,this.w+=e.w,this}addScalar(e){return this.x+=e,this.y+=e,this.z+=e,this.w+=e,this}addVectors(e,t){return this.x=e.x+t.x,this.y=e.y+t.y,this.z=e.z+t.z,this.w=e.w+t.w,this}addScaledVector(e,t){return this.x+=e.x*t,this.y+=e.y*t,this.z+=e.z*t,this.w+=e.w*t,this}sub(e){return this.x-=e.x,this.y-=e.y,this.z-=e.z,this.w-=e.w,this}subScalar(e){return this.x-=e,this.y-=e,this.z-=e,this.w-=e,this}subVectors(e,t){return this.x=e.x-t.x,this.y=e.y-t.y,this.z=e.z-t.z,this.w=e.w-t.w,this}multiply(e){return this.x*=e.x,this.y*=e.y,this.z*=e.z,this.w*=e.w,this}multiplyScalar(e){return this.x*=e,this.y*=e,this.z*=e,this.w*=e,this}applyMatrix4(e){let t=this.x,i=this.y,r=this.z,s=this.w,o=e.elements;return this.x=o[0]*t+o[4]*i+o[8]*r+o[12]*s,this.y=o[1]*t+o[5]*i+o[9]*r+o[13]*s,this.z=o[2]*t+o[6]*i+o[10]*r+o[14]*s,this.w=o[3]*t+o[7]*i+o[11]*r+o[15]*s,this}divide(e){return this.x/=e.x,this.y/=e.y,this.z/=e.z,this.w/=e.w,this}divideScalar(e){return this.multiplyScalar(1/e)}setAxisAngleFromQuaternion(e){this.w=2*Math.acos(e.w);let t=Math.sqrt(1-e.w*e.w);return t<1e-4?(this.x=1,this.y=0,this.z=0):(this.x=e.x/t,this.y=e.y/t,this.z=e.z/t),this}setAxisAngleFromRotationMatrix(e){let t,i,r,s,l=e.elements,c=l[0],u=l[4],h=l[8],f=l[1],d=l[5],p=l[9],x=l[2],m=l[6],g=l[10];if(Math.abs(u-f)<.01&&Math.abs(h-x)<.01&&Math.abs(p-m)<.01){if(Math.abs(u+f)<.1&&Math.abs(h+x)<.1&&Math.abs(p+m)<.1&&Math.abs(c+d+g-3)<.1)return this.set(1,0,0,0),this;t=Math.PI;let T=(c+1)/2,v=(d+1)/2,R=(g+1)/2,A=(u+f)/4,_=(h+x)/4,E=(p+m)/4;return T>v&&T>R?T<.01?(i=0,r=.707106781,s=.707106781):(i=Math.sqrt(T),r=A/i,s=_/i):v>R?v<.01?(i=.707106781,r=0,s=.707106781):(r=Math.sqrt(v),i=A/r,s=E/r):R<.01?(i=.707106781,r=.707106781,s=0):(s=Math.sqrt(R),i=_/s,r=E/s),this.set(i,r,s,t),this}let b=Math.sqrt((m-p)*(m-p)+(h-x)*(h-x)+(f-u)*(f-u));return Math.abs(b)<.001&&(b=1),this.x=(m-p)/b,this.y=(h-x)/b,this.z=(f-u)/b,this.w=Math.acos((c+d+g-1)/2),this}setFromMatrixPosition(e){let t=e.elements;return this.x=t[12],this.y=t[13],this.z=t[14],this.w=t[15],this}min(e){return this.x=Math.min(this.x,e.x),this.y=Math.min(this.y,e.y),this.z=Math.min(this.z,e.z),this.w=Math.min(this.w,e.w),this}max(e){return this.x=Math.max(this.x,e.x),this.y=Math.max(this.y,e.y),this.z=Math.max(this.z,e.z),this.w=Math.max(this.w,e.w),this}clamp(e,t){return this.x=_t(this.x,e.x,t.x),this.y=_t(this.y,e.y,t.y),this.z=_t(this.z,e.z,t.z),this.w=_t(this.w,e.w,t.w),this}clampScalar(e,t){return this.x=_t(this.x,e,t),this.y=_t(this.y,e,t),this.z=_t(this.z,e,t),this.w=_t(this.w,e,t),this}clampLength(e,t){let i=this.length();return this.divideScalar(i||1).multiplyScalar(_t(i,e,t))}floor(){return this.x=Math.floor(this.x),this.y=Math.floor(this.y),this.z=Math.floor(this.z),this.w=Math.floor(this.w),this}ceil(){return this.x=Math.ceil(this.x),this.y=Math.ceil(this.y),this.z=Math.ceil(this.z),this.w=Math.ceil(this.w),this}round(){return this.x=Math.round(this.x),this.y=Math.round(this.y),this.z=Math.round(this.z),this.w=Math.round(this.w),this}roundToZero(){return this.x=Math.trunc(this.x),this.y=Math.trunc(this.y),this.z=Math.trunc(this.z),this.w=Math.trunc(this.w),this}negate(){return this.x=-this.x,this.y=-this.y,this.z=-this.z,this.w=-this.w,this}dot(e){return this.x*e.x+this.y*e.y+this.z*e.z+this.w*e.w}lengthSq(){return this.x*this.x+this.y*this.y+this.z*this.z+this.w*this.w}length(){return Math.sqrt(this.x*this.x+this.y*this.y+this.z*this.z+this.w*this.w)}manhattanLength(){return Math.abs(this.x)+Math.abs(this.y)+Math.abs(this.z)+Math.abs(this.w)}normalize(){return this.divideScalar(this.length()||1)}setLength(e){return this.normalize().multiplyScalar(e)}lerp(e,t){return this.x+=(e.x-this.x)*t,this.y+=(e.y-this.y)*t,this.z+=(e.z-this.z)*t,this.w+=(e.w-this.w)*t,this}lerpVectors(e,t,i){return this.x=e.x+(t.x-e.x)*i,this.y=e.y+(t.y-e.y)*i,this.z=e.z+(t.z-e.z)*i,this.w=e.w+(t.w-e.w)*i,this}equals(e){return e.x===this.x&&e.y===this.y&&e.z===this.z&&e.w===this.w}fromArray(e,t=0){return this.x=e[t],this.y=e[t+1],this.z=e[t+2],this.w=e[t+3],this}toArray(e=[],t=0){return e[t]=this.x,e[t+1]=this.y,e[t+2]=this.z,e[t+3]=this.w,e}fromBufferAttribute(e,t){return this.x=e.getX(t),this.y=e.getY(t),this.z=e.getZ(t),this.w=e.getW(t),this}random(){return this.x=Math.random(),this.y=Math.random(),this.z=Math.random(),this.w=Math.random(),this}*[Symbol.iterator](){yield this.x,yield this.y,yield this.z,yield this.w}},Fu=class extends qi{constructor(e=1,t=1,i={}){super(),i=Object.assign({generateMipmaps:!1,internalFormat:null,minFilter:ri,depthBuffer:!0,stencilBuffer:!1,resolveColorBuffer:!0,resolveDepthBuffer:!0,resolveStencilBuffer:!0,storeMultisampledColorBuffer:!0,storeMultisampledDepthBuffer:!0,storeMultisampledStencilBuffer:!0,depthTexture:null,samples:0,count:1,depth:1,multiview:!1,useArrayDepthTexture:!1},i),this.isRenderTarget=!0,this.width=e,this.height=t,this.depth=i.depth,this.scissor=new tn(0,0,e,t),this.scissorTest=!1,this.viewport=new tn(0,0,e,t),this.textures=[];let r=i.count;for(let s=0;s<r;s++)this.textures[s]=new ai({width:e,height:t,depth:i.depth}),this.textures[s].isRenderTargetTexture=!0,this.textures[s].renderTarget=this;this._setTextureOptions(i),this.depthBuffer=i.depthBuffer,this.stencilBuffer=i.stencilBuffer,this.resolveColorBuffer=i.resolveColorBuffer,this.resolveDepthBuffer=i.resolveDepthBuffer,this.resolveStencilBuffer=i.resolveStencilBuffer,this.storeMultisampledColorBuffer=i.storeMultisampledColorBuffer,this.storeMultisampledDepthBuffer=i.storeMultisampledDepthBuffer,this.storeMultisampledStencilBuffer=i.storeMultisampledStencilBuffer,this._depthTexture=null,this.depthTexture=i.depthTexture,this.samples=i.samples,this.multiview=i.multiview,this.useArrayDepthTexture=i.useArrayDepthTexture}_setTextureOptions(e={}){let t={minFilter:ri,generateMipmaps:!1,flipY:!1,internalFormat:null};e.mapping!==void 0&&(t.mapping=e.mapping),e.wrapS!==void 0&&(t.wrapS=e.wrapS),e.wrapT!==void 0&&(t.wrapT=e.wrapT),e.wrapR!==void 0&&(t.wrapR=e.wrapR),e.magFilter!==void 0&&(t.magFilter=e.magFilter),e.minFilter!==void 0&&(t.minFilter=e.minFilter),e.format!==void 0&&(t.format=e.format),e.type!==void 0&&(t.type=e.type),e.anisotropy!==void 0&&(t.anisotropy=e.anisotropy),e.colorSpace!==void 0&&(t.colorSpace=e.colorSpace),e.flipY!==void 0&&(t.flipY=e.flipY),e.generateMipmaps!==void 0&&(t.generateMipmaps=e.generateMipmaps),e.mipmapsAutoUpdate!==void 0&&(t.mipmapsAutoUpdate=e.mipmapsAutoUpdate),e.internalFormat!==void 0&&(t.internalFormat=e.internalFormat);for(let i=0;i<this.textures.length;i++)this.textures[i].setValues(t)}get texture(){return this.textures[0]}set texture(e){this.textures[0]=e}set depthTexture(e){this._depthTexture!==null&&this._depthTexture.renderTarget===this&&(this._depthTexture.renderTarget=null),e!==null&&e.renderTarget===null&&(e.renderTarget=this),this._depthTexture=e}get depthTexture(){return this._depthTexture}setSize(e,t,i=1){if(this.width!==e||this.height!==t||this.depth!==i){this.width=e,this.height=t,this.depth=i;for(let r=0,s=this.textures.length;r<s;r++)this.textures[r].image.width=e,this.textures[r].image.height=t,this.textures[r].image.depth=i,this.textures[r].isData3DTexture!==!0&&(this.textures[r].isArrayTexture=this.textures[r].image.depth>1);this.dispose()}this.viewport.set(0,0,e,t),this.scissor.set(0,0,e,t)}clone(){return new this.constructor().copy(this)}copy(e){this.width=e.width,this.height=e.height,this.depth=e.depth,this.scissor.copy(e.scissor),this.scissorTest=e.scissorTest,this.viewport.copy(e.viewport),this.textures.length=0;for(let t=0,i=e.textures.length;t<i;t++){this.textures[t]=e.textures[t].clone(),this.textures[t].isRenderTargetTexture=!0,this.textures[t].renderTarget=this;let r=Object.assign({},e.textures[t].image);this.textures[t].source=new Yo(r)}if(this.depthBuffer=e.depthBuffer,this.stencilBuffer=e.stencilBuffer,this.resolveColorBuffer=e.resolveColorBuffer,this.resolveDepthBuffer=e.resolveDepthBuffer,this.resolveStencilBuffer=e.resolveStencilBuffer,this.storeMultisampledColorBuffer=e.storeMultisampledColorBuffer,this.storeMultisampledDepthBuffer=e.storeMultisampledDepthBuffer,this.storeMultisampledStencilBuffer=e.storeMultisampledStencilBuffer,e.depthTexture!==null)if(e.depthTexture.renderTarget===e){let t=e.depthTexture.clone();t.renderTarget=null,this.depthTexture=t}else this.depthTexture=e.depthTexture;else this.depthTexture=null;return this.samples=e.samples,this.multiview=e.multiview,this.useArrayDepthTexture=e.useArrayDepthTexture,this}dispose(){this.dispatchEvent({type:"dispose"})}},wi=class extends Fu{constructor(e=1,t=1,i={}){super(e,t,i),this.isWebGLRenderTarget=!0}},sl=class extends ai{constructor(e=null,t=1,i=1,r=1){super(null),this.isDataArrayTexture=!0,this.image={data:e,width:t,height:i,depth:r},this.magFilter=Vn,this.minFilter=Vn,this.wrapR=mr,this.generateMipmaps=!1,this.flipY=!1,this.unpackAlignment=1,this.layerUpdates=new Set}copy(e){return super.copy(e),this.wrapR=e.wrapR,this}addLayerUpdate(e){this.layerUpdates.add(e)}clearLayerUpdates(){this.layerUpdates.clear()}};var Uu=class extends ai{constructor(e=null,t=1,i=1,r=1){super(null),this.isData3DTexture=!0,this.image={data:e,width:t,height:i,depth:r},this.magFilter=Vn,this.minFilter=Vn,this.wrapR=mr,this.generateMipmaps=!1,this.flipY=!1,this.unpackAlignment=1}copy(e){return super.copy(e),this.wrapR=e.wrapR,this}};var Tt=class n{static{this.prototype.isMatrix4=!0}constructor(e,t,i,r,s,o,a,l,c,u,h,f,d,p,x,m){this.elements=[1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1],e!==void 0&&this.set(e,t,i,r,s,o,a,l,c,u,h,f,d,p,x,m)}set(e,t,i,r,s,o,a,l,c,u,h,f,d,p,x,m){let g=this.elements;return g[0]=e,g[4]=t,g[8]=i,g[12]=r,g[1]=s,g[5]=o,g[9]=a,g[13]=l,g[2]=c,g[6]=u,g[10]=h,g[14]=f,g[3]=d,g[7]=p,g[11]=x,g[15]=m,this}identity(){return this.set(1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1),this}clone(){return new n().fromArray(this.elements)}copy(e){let t=this.elements,i=e.elements;return t[0]=i[0],t[1]=i[1],t[2]=i[2],t[3]=i[3],t[4]=i[4],t[5]=i[5],t[6]=i[6],t[7]=i[7],t[8]=i[8],t[9]=i[9],t[10]=i[10],t[11]=i[11],t[12]=i[12],t[13]=i[13],t[14]=i[14],t[15]=i[15],this}copyPosition(e){let t=this.elements,i=e.elements;return t[12]=i[12],t[13]=i[13],t[14]=i[14],this}setFromMatrix3(e){let t=e.elements;return this.set(t[0],t[3],t[6],0,t[1],t[4],t[7],0,t[2],t[5],t[8],0,0,0,0,1),this}extractBasis(e,t,i){return this.determinantAffine()===0?(e.set(1,0,0),t.set(0,1,0),i.set(0,0,1),this):(e.setFromMatrixColumn(this,0),t.setFromMatrixColumn(this,1),i.setFromMatrixColumn(this,2),this)}makeBasis(e,t,i){return this.set(e.x,t.x,i.x,0,e.y,t.y,i.y,0,e.z,t.z,i.z,0,0,0,0,1),this}extractRotation(e){if(e.determinantAffine()===0)return this.identity();let t=this.elements,i=e.elements,r=1/Ao.setFromMatrixColumn(e,0).length(),s=1/Ao.setFromMatrixColumn(e,1).length(),o=1/Ao.setFromMatrixColumn(e,2).length();return t[0]=i[0]*r,t[1]=i[1]*r,t[2]=i[2]*r,t[3]=0,t[4]=i[4]*s,t[5]=i[5]*s,t[6]=i[6]*s,t[7]=0,t[8]=i[8]*o,t[9]=i[9]*o,t[10]=i[10]*o,t[11]=0,t[12]=0,t[13]=0,t[14]=0,t[15]=1,this}makeRotationFromEuler(e){let t=this.elements,i=e.x,r=e.y,s=e.z,o=Math.cos(i),a=Math.sin(i),l=Math.cos(r),c=Math.sin(r),u=Math.cos(s),h=Math.sin(s);if(e.order==="XYZ"){let f=o*u,d=o*h,p=a*u,x=a*h;t[0]=l*u,t[4]=-l*h,t[8]=c,t[1]=d+p*c,t[5]=f-x*c,t[9]=-a*l,t[2]=x-f*c,t[6]=p+d*c,t[10]=o*l}else if(e.order==="YXZ"){let f=l*u,d=l*h,p=c*u,x=c*h;t[0]=f+x*a,t[4]=p*a-d,t[8]=o*c,t[1]=o*h,t[5]=o*u,t[9]=-a,t[2]=d*a-p,t[6]=x+f*a,t[10]=o*l}else if(e.order==="ZXY"){let f=l*u,d=l*h,p=c*u,x=c*h;t[0]=f-x*a,t[4]=-o*h,t[8]=p+d*a,t[1]=d+p*a,t[5]=o*u,t[9]=x-f*a,t[2]=-o*c,t[6]=a,t[10]=o*l}else if(e.order==="ZYX"){let f=o*u,d=o*h,p=a*u,x=a*h;t[0]=l*u,t[4]=p*c-d,t[8]=f*c+x,t[1]=l*h,t[5]=x*c+f,t[9]=d*c-p,t[2]=-c,t[6]=a*l,t[10]=o*l}else if(e.order==="YZX"){let f=o*l,d=o*c,p=a*l,x=a*c;t[0]=l*u,t[4]=x-f*h,t[8]=p*h+d,t[1]=h,t[5]=o*u,t[9]=-a*u,t[2]=-c*u,t[6]=d*h+p,t[10]=f-x*h}else if(e.order==="XZY"){let f=o*l,d=o*c,p=a*l,x=a*c;t[0]=l*u,t[4]=-h,t[8]=c*u,t[1]=f*h+x,t[5]=o*u,t[9]=d*h-p,t[2]=p*h-d,t[6]=a*u,t[10]=x*h+f}return t[3]=0,t[7]=0,t[11]=0,t[12]=0,t[13]=0,t[14]=0,t[15]=1,this}makeRotationFromQuaternion(e){return this.compose(yA,e,xA)}lookAt(e,t,i){let r=this.elements;return bi.subVectors(e,t),bi.lengthSq()===0&&(bi.z=1),bi.normalize(),ss.crossVectors(i,bi),ss.lengthSq()===0&&(Math.abs(i.z)===1?bi.x+=1e-4:bi.z+=1e-4,bi.normalize(),ss.crossVectors(i,bi)),ss.normalize(),qc.crossVectors(bi,ss),r[0]=ss.x,r[4]=qc.x,r[8]=bi.x,r[1]=ss.y,r[5]=qc.y,r[9]=bi.y,r[2]=ss.z,r[6]=qc.z,r[10]=bi.z,this}multiply(e){return this.multiplyMatrices(this,e)}premultiply(e){return this.multiplyMatrices(e,this)}multiplyMatrices(e,t){let i=e.elements,r=t.elements,s=this.elements,o=i[0],a=i[4],l=i[8],c=i[12],u=i[1],h=i[5],f=i[9],d=i[13],p=i[2],x=i[6],m=i[10],g=i[14],b=i[3],T=i[7],v=i[11],R=i[15],A=r[0],_=r[4],E=r[8],F=r[12],N=r[1],P=r[5],k=r[9],H=r[13],D=r[2],W=r[6],K=r[10],z=r[14],ce=r[3],J=r[7],Q=r[11],re=r[15];return s[0]=o*A+a*N+l*D+c*ce,s[4]=o*_+a*P+l*W+c*J,s[8]=o*E+a*k+l*K+c*Q,s[12]=o*F+a*H+l*z+c*re,s[1]=u*A+h*N+f*D+d*ce,s[5]=u*_+h*P+f*W+d*J,s[9]=u*E+h*k+f*K+d*Q,s[13]=u*F+h*H+f*z+d*re,s[2]=p*A+x*N+m*D+g*ce,s[6]=p*_+x*P+m*W+g*J,s[10]=p*E+x*k+m*K+g*Q,s[14]=p*F+x*H+m*z+g*re,s[3]=b*A+T*N+v*D+R*ce,s[7]=b*_+T*P+v*W+R*J,s[11]=b*E+T*k+v*K+R*Q,s[15]=b*F+T*H+v*z+R*re,this}multiplyScalar(e){let t=this.elements;return t[0]*=e,t[4]*=e,t[8]*=e,t[12]*=e,t[1]*=e,t[5]*=e,t[9]*=e,t[13]*=e,t[2]*=e,t[6]*=e,t[10]*=e,t[14]*=e,t[3]*=e,t[7]*=e,t[11]*=e,t[15]*=e,this}determinant(){let e=this.elements,t=e[0],i=e[4],r=e[8],s=e[12],o=e[1],a=e[5],l=e[9],c=e[13],u=e[2],h=e[6],f=e[10],d=e[14],p=e[3],x=e[7],m=e[11],g=e[15],b=l*d-c*f,T=a*d-c*h,v=a*f-l*h,R=o*d-c*u,A=o*f-l*u,_=o*h-a*u;return t*(x*b-m*T+g*v)-i*(p*b-m*R+g*A)+r*(p*T-x*R+g*_)-s*(p*v-x*A+m*_)}determinantAffine(){let e=this.elements,t=e[0],i=e[4],r=e[8],s=e[1],o=e[5],a=e[9],l=e[2],c=e[6],u=e[10];return t*(o*u-a*c)-i*(s*u-a*l)+r*(s*c-o*l)}transpose(){let e=this.elements,t;return t=e[1],e[1]=e[4],e[4]=t,t=e[2],e[2]=e[8],e[8]=t,t=e[6],e[6]=e[9],e[9]=t,t=e[3],e[3]=e[12],e[12]=t,t=e[7],e[7]=e[13],e[13]=t,t=e[11],e[11]=e[14],e[14]=t,this}setPosition(e,t,i){let r=this.elements;return e.isVector3?(r[12]=e.x,r[13]=e.y,r[14]=e.z):(r[12]=e,r[13]=t,r[14]=i),this}invert(){let e=this.elements,t=e[0],i=e[1],r=e[2],s=e[3],o=e[4],a=e[5],l=e[6],c=e[7],u=e[8],h=e[9],f=e[10],d=e[11],p=e[12],x=e[13],m=e[14],g=e[15],b=t*a-i*o,T=t*l-r*o,v=t*c-s*o,R=i*l-r*a,A=i*c-s*a,_=r*c-s*l,E=u*x-h*p,F=u*m-f*p,N=u*g-d*p,P=h*m-f*x,k=h*g-d*x,H=f*g-d*m,D=b*H-T*k+v*P+R*N-A*F+_*E;if(D===0)return this.set(0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0);let W=1/D;return e[0]=(a*H-l*k+c*P)*W,e[1]=(r*k-i*H-s*P)*W,e[2]=(x*_-m*A+g*R)*W,e[3]=(f*A-h*_-d*R)*W,e[4]=(l*N-o*H-c*F)*W,e[5]=(t*H-r*N+s*F)*W,e[6]=(m*v-p*_-g*T)*W,e[7]=(u*_-f*v+d*T)*W,e[8]=(o*k-a*N+c*E)*W,e[9]=(i*N-t*k-s*E)*W,e[10]=(p*A-x*v+g*b)*W,e[11]=(h*v-u*A-d*b)*W,e[12]=(a*F-o*P-l*E)*W,e[13]=(t*P-i*F+r*E)*W,e[14]=(x*T-p*R-m*b)*W,e[15]=(u*R-h*T+f*b)*W,this}scale(e){let t=this.elements,i=e.x,r=e.y,s=e.z;return t[0]*=i,t[4]*=r,t[8]*=s,t[1]*=i,t[5]*=r,t[9]*=s,t[2]*=i,t[6]*=r,t[10]*=s,t[3]*=i,t[7]*=r,t[11]*=s,this}getMaxScaleOnAxis(){let e=this.elements,t=e[0]*e[0]+e[1]*e[1]+e[2]*e[2],i=e[4]*e[4]+e[5]*e[5]+e[6]*e[6],r=e[8]*e[8]+e[9]*e[9]+e[10]*e[10];return Math.sqrt(Math.max(t,i,r))}makeTranslation(e,t,i){return e.isVector3?this.set(1,0,0,e.x,0,1,0,e.y,0,0,1,e.z,0,0,0,1):this.set(1,0,0,e,0,1,0,t,0,0,1,i,0,0,0,1),this}makeRotationX(e){let t=Math.cos(e),i=Math.sin(e);return this.set(1,0,0,0,0,t,-i,0,0,i,t,0,0,0,0,1),this}makeRotationY(e){let t=Math.cos(e),i=Math.sin(e);return this.set(t,0,i,0,0,1,0,0,-i,0,t,0,0,0,0,1),this}makeRotationZ(e){let t=Math.cos(e),i=Math.sin(e);return this.set(t,-i,0,0,i,t,0,0,0,0,1,0,0,0,0,1),this}makeRotationAxis(e,t){let i=Math.cos(t),r=Math.sin(t),s=1-i,o=e.x,a=e.y,l=e.z,c=s*o,u=s*a;return this.set(c*o+i,c*a-r*l,c*l+r*a,0,c*a+r*l,u*a+i,u*l-r*o,0,c*l-r*a,u*l+r*o,s*l*l+i,0,0,0,0,1),this}makeScale(e,t,i){return this.set(e,0,0,0,0,t,0,0,0,0,i,0,0,0,0,1),this}makeShear(e,t,i,r,s,o){return this.set(1,i,s,0,e,1,o,0,t,r,1,0,0,0,0,1),this}compose(e,t,i){let r=this.elements,s=t._x,o=t._y,a=t._z,l=t._w,c=s+s,u=o+o,h=a+a,f=s*c,d=s*u,p=s*h,x=o*u,m=o*h,g=a*h,b=l*c,T=l*u,v=l*h,R=i.x,A=i.y,_=i.z;return r[0]=(1-(x+g))*R,r[1]=(d+v)*R,r[2]=(p-T)*R,r[3]=0,r[4]=(d-v)*A,r[5]=(1-(f+g))*A,r[6]=(m+b)*A,r[7]=0,r[8]=(p+T)*_,r[9]=(m-b)*_,r[10]=(1-(f+x))*_,r[11]=0,r[12]=e.x,r[13]=e.y,r[14]=e.z,r[15]=1,this}decompose(e,t,i){let r=this.elements;e.x=r[12],e.y=r[13],e.z=r[14];let s=this.determinantAffine();if(s===0)return i.set(1,1,1),t.identity(),this;let o=Ao.set(r[0],r[1],r[2]).length(),a=Ao.set(r[4],r[5],r[6]).length(),l=Ao.set(r[8],r[9],r[10]).length();s<0&&(o=-o),Zi.copy(this);let c=1/o,u=1/a,h=1/l;return Zi.elements[0]*=c,Zi.elements[1]*=c,Zi.elements[2]*=c,Zi.elements[4]*=u,Zi.elements[5]*=u,Zi.elements[6]*=u,Zi.elements[8]*=h,Zi.elements[9]*=h,Zi.elements[10]*=h,t.setFromRotationMatrix(Zi),i.x=o,i.y=a,i.z=l,this}makePerspective(e,t,i,r,s,o,a=Di,l=!1){let c=this.elements,u=2*s/(t-e),h=2*s/(i-r),f=(t+e)/(t-e),d=(i+r)/(i-r),p,x;if(l)p=s/(o-s),x=o*s/(o-s);else if(a===Di)p=-(o+s)/(o-s),x=-2*o*s/(o-s);else if(a===Ho)p=-o/(o-s),x=-o*s/(o-s);else throw new Error("THREE.Matrix4.makePerspective(): Invalid coordinate system: "+a);return c[0]=u,c[4]=0,c[8]=f,c[12]=0,c[1]=0,c[5]=h,c[9]=d,c[13]=0,c[2]=0,c[6]=0,c[10]=p,c[14]=x,c[3]=0,c[7]=0,c[11]=-1,c[15]=0,this}makeOrthographic(e,t,i,r,s,o,a=Di,l=!1){let c=this.elements,u=2/(t-e),h=2/(i-r),f=-(t+e)/(t-e),d=-(i+r)/(i-r),p,x;if(l)p=1/(o-s),x=o/(o-s);else if(a===Di)p=-2/(o-s),x=-(o+s)/(o-s);else if(a===Ho)p=-1/(o-s),x=-s/(o-s);else throw new Error("THREE.Matrix4.makeOrthographic(): Invalid coordinate system: "+a);return c[0]=u,c[4]=0,c[8]=0,c[12]=f,c[1]=0,c[5]=h,c[9]=0,c[13]=d,c[2]=0,c[6]=0,c[10]=p,c[14]=x,c[3]=0,c[7]=0,c[11]=0,c[15]=1,this}equals(e){let t=this.elements,i=e.elements;for(let r=0;r<16;r++)if(t[r]!==i[r])return!1;return!0}fromArray(e,t=0){for(let i=0;i<16;i++)this.elements[i]=e[i+t];return this}toArray(e=[],t=0){let i=this.elements;return e[t]=i[0],e[t+1]=i[1],e[t+2]=i[2],e[t+3]=i[3],e[t+4]=i[4],e[t+5]=i[5],e[t+6]=i[6],e[t+7]=i[7],e[t+8]=i[8],e[t+9]=i[9],e[t+10]=i[10],e[t+11]=i[11],e[t+12]=i[12],e[t+13]=i[13],e[t+14]=i[14],e[t+15]=i[15],e}},Ao=new X,Zi=new Tt,yA=new X(0,0,0),xA=new X(1,1,1),ss=new X,qc=new X,bi=new X,Bx=new Tt,kx=new Mi,Ji=class n{constructor(e=0,t=0,i=0,r=n.DEFAULT_ORDER){this.isEuler=!0,this._x=e,this._y=t,this._z=i,this._order=r}get x(){return this._x}set x(e){this._x=e,this._onChangeCallback()}get y(){return this._y}set y(e){this._y=e,this._onChangeCallback()}get z(){return this._z}set z(e){this._z=e,this._onChangeCallback()}get order(){return this._order}set order(e){this._order=e,this._onChangeCallback()}set(e,t,i,r=this._order){return this._x=e,this._y=t,this._z=i,this._order=r,this._onChangeCallback(),this}clone(){return new this.constructor(this._x,this._y,this._z,this._order)}copy(e){return this._x=e._x,this._y=e._y,this._z=e._z,this._order=e._order,this._onChangeCallback(),this}setFromRotationMatrix(e,t=this._order,i=!0){let r=e.elements,s=r[0],o=r[4],a=r[8],l=r[1],c=r[5],u=r[9],h=r[2],f=r[6],d=r[10];switch(t){case"XYZ":this._y=Math.asin(_t(a,-1,1)),Math.abs(a)<.9999999?(this._x=Math.atan2(-u,d),this._z=Math.atan2(-o,s)):(this._x=Math.atan2(f,c),this._z=0);break;case"YXZ":this._x=Math.asin(-_t(u,-1,1)),Math.abs(u)<.9999999?(this._y=Math.atan2(a,d),this._z=Math.atan2(l,c)):(this._y=Math.atan2(-h,s),this._z=0);break;case"ZXY":this._x=Math.asin(_t(f,-1,1)),Math.abs(f)<.9999999?(this._y=Math.atan2(-h,d),this._z=Math.atan2(-o,c)):(this._y=0,this._z=Math.atan2(l,s));break;case"ZYX":this._y=Math.asin(-_t(h,-1,1)),Math.abs(h)<.9999999?(this._x=Math.atan2(f,d),this._z=Math.atan2(l,s)):(this._x=0,this._z=Math.atan2(-o,c));break;case"YZX":this._z=Math.asin(_t(l,-1,1)),Math.abs(l)<.9999999?(this._x=Math.atan2(-u,c),this._y=Math.atan2(-h,s)):(this._x=0,this._y=Math.atan2(a,d));break;case"XZY":this._z=Math.asin(-_t(o,-1,1)),Math.abs(o)<.9999999?(this._x=Math.atan2(f,c),this._y=Math.atan2(a,s)):(this._x=Math.atan2(-u,d),this._y=0);break;default:$e("Euler: .setFromRotationMatrix() encountered an unknown order: "+t)}return this._order=t,i===!0&&this._onChangeCallback(),this}setFromQuaternion(e,t,i){return Bx.makeRotationFromQuaternion(e),this.setFromRotationMatrix(Bx,t,i)}setFromVector3(e,t=this._order){return this.set(e.x,e.y,e.z,t)}reorder(e){return kx.setFromEuler(this),this.setFromQuaternion(kx,e)}equals(e){return e._x===this._x&&e._y===this._y&&e._z===this._z&&e._order===this._order}fromArray(e){return this._x=e[0],this._y=e[1],this._z=e[2],e[3]!==void 0&&(this._order=e[3]),this._onChangeCallback(),this}toArray(e=[],t=0){return e[t]=this._x,e[t+1]=this._y,e[t+2]=this._z,e[t+3]=this._order,e}_onChange(e){return this._onChangeCallback=e,this}_onChangeCallback(){}*[Symbol.iterator](){yield this._x,yield this._y,yield this._z,yield this._order}};Ji.DEFAULT_ORDER="XYZ";var Zo=class{constructor(){this.mask=1}set(e){this.mask=(1<<e|0)>>>0}enable(e){this.mask|=1<<e|0}enableAll(){this.mask=-1}toggle(e){this.mask^=1<<e|0}disable(e){this.mask&=~(1<<e|0)}disableAll(){this.mask=0}test(e){return(this.mask&e.mask)!==0}isEnabled(e){return(this.mask&(1<<e|0))!==0}},bA=0,Vx=new X,Ro=new Mi,Pr=new Tt,Jc=new X,Ya=new X,vA=new X,SA=new Mi,Gx=new X(1,0,0),zx=new X(0,1,0),Hx=new X(0,0,1),Wx={type:"added"},EA={type:"removed"},Io={type:"childadded",child:null},dp={type:"childremoved",child:null},Xn=class n extends qi{constructor(){super(),this.isObject3D=!0,Object.defineProperty(this,"id",{value:bA++}),this.uuid=ra(),this.name="",this.type="Object3D",this.parent=null,this.children=[],this.up=n.DEFAULT_UP.clone();let e=new X,t=new Ji,i=new Mi,r=new X(1,1,1);function s(){i.setFromEuler(t,!1)}function o(){t.setFromQuaternion(i,void 0,!1)}t._onChange(s),i._onChange(o),Object.defineProperties(this,{position:{configurable:!0,enumerable:!0,value:e},rotation:{configurable:!0,enumerable:!0,value:t},quaternion:{configurable:!0,enumerable:!0,value:i},scale:{configurable:!0,enumerable:!0,value:r},modelViewMatrix:{value:new Tt},normalMatrix:{value:new it}}),this.matrix=new Tt,this.matrixWorld=new Tt,this.matrixAutoUpdate=n.DEFAULT_MATRIX_AUTO_UPDATE,this.matrixWorldAutoUpdate=n.DEFAULT_MATRIX_WORLD_AUTO_UPDATE,this.matrixWorldNeedsUpdate=!1,this.layers=new Zo,this.visible=!0,this.castShadow=!1,this.receiveShadow=!1,this.frustumCulled=!0,this.renderOrder=0,this.animations=[],this.customDepthMaterial=void 0,this.customDistanceMaterial=void 0,this.static=!1,this.userData={},this.pivot=null}onBeforeShadow(){}onAfterShadow(){}onBeforeRender(){}onAfterRender(){}applyMatrix4(e){this.matrixAutoUpdate&&this.updateMatrix(),this.matrix.premultiply(e),this.matrix.decompose(this.position,this.quaternion,this.scale),this.pivot!==null&&this.position.copy(this.pivot).applyMatrix4(this.matrix).sub(this.pivot)}applyQuaternion(e){return this.quaternion.premultiply(e),this}setRotationFromAxisAngle(e,t){this.quaternion.setFromAxisAngle(e,t)}setRotationFromEuler(e){this.quaternion.setFromEuler(e,!0)}setRotationFromMatrix(e){this.quaternion.setFromRotationMatrix(e)}setRotationFromQuaternion(e){this.quaternion.copy(e)}rotateOnAxis(e,t){return Ro.setFromAxisAngle(e,t),this.quaternion.multiply(Ro),this}rotateOnWorldAxis(e,t){return Ro.setFromAxisAngle(e,t),this.quaternion.premultiply(Ro),this}rotateX(e){return this.rotateOnAxis(Gx,e)}rotateY(e){return this.rotateOnAxis(zx,e)}rotateZ(e){return this.rotateOnAxis(Hx,e)}translateOnAxis(e,t){return Vx.copy(e).applyQuaternion(this.quaternion),this.position.add(Vx.multiplyScalar(t)),this}translateX(e){return this.translateOnAxis(Gx,e)}translateY(e){return this.translateOnAxis(zx,e)}translateZ(e){return this.translateOnAxis(Hx,e)}localToWorld(e){return this.updateWorldMatrix(!0,!1),e.applyMatrix4(this.matrixWorld)}worldToLocal(e){return this.updateWorldMatrix(!0,!1),e.applyMatrix4(Pr.copy(this.matrixWorld).invert())}lookAt(e,t,i){e.isVector3?Jc.copy(e):Jc.set(e,t,i);let r=this.parent;this.updateWorldMatrix(!0,!1),Ya.setFromMatrixPosition(this.matrixWorld),this.isCamera||this.isLight?Pr.lookAt(Ya,Jc,this.up):Pr.lookAt(Jc,Ya,this.up),this.quaternion.setFromRotationMatrix(Pr),r&&(Pr.extractRotation(r.matrixWorld),Ro.setFromRotationMatrix(Pr),this.quaternion.premultiply(Ro.invert()))}add(e){if(arguments.length>1){for(let t=0;t<arguments.length;t++)this.add(arguments[t]);return this}return e===this?(et("Object3D.add: object can't be added as a child of itself.",e),this):(e&&e.isObject3D?(e.removeFromParent(),e.parent=this,this.children.push(e),e.dispatchEvent(Wx),Io.child=e,this.dispatchEvent(Io),Io.child=null):et("Object3D.add: object not an instance of THREE.Object3D.",e),this)}remove(e){if(arguments.length>1){for(let i=0;i<arguments.length;i++)this.remove(arguments[i]);return this}let t=this.children.indexOf(e);return t!==-1&&(e.parent=null,this.children.splice(t,1),e.dispatchEvent(EA),dp.child=e,this.dispatchEvent(dp),dp.child=null),this}removeFromParent(){let e=this.parent;return e!==null&&e.remove(this),this}clear(){return this.remove(...this.children)}attach(e){return this.updateWorldMatrix(!0,!1),Pr.copy(this.matrixWorld).invert(),e.parent!==null&&(e.parent.updateWorldMatrix(!0,!1),Pr.multiply(e.parent.matrixWorld)),e.applyMatrix4(Pr),e.removeFromParent(),e.parent=this,this.children.push(e),e.updateWorldMatrix(!1,!0),e.dispatchEvent(Wx),Io.child=e,this.dispatchEvent(Io),Io.child=null,this}getObjectById(e){return this.getObjectByProperty("id",e)}getObjectByName(e){return this.getObjectByProperty("name",e)}getObjectByProperty(e,t){if(this[e]===t)return this;for(let i=0,r=this.children.length;i<r;i++){let o=this.children[i].getObjectByProperty(e,t);if(o!==void 0)return o}}getObjectsByProperty(e,t,i=[]){this[e]===t&&i.push(this);let r=this.children;for(let s=0,o=r.length;s<o;s++)r[s].getObjectsByProperty(e,t,i);return i}getWorldPosition(e){return this.updateWorldMatrix(!0,!1),e.setFromMatrixPosition(this.matrixWorld)}getWorldQuaternion(e){return this.updateWorldMatrix(!0,!1),this.matrixWorld.decompose(Ya,e,vA),e}getWorldScale(e){return this.updateWorldMatrix(!0,!1),this.matrixWorld.decompose(Ya,SA,e),e}getWorldDirection(e){this.updateWorldMatrix(!0,!1);let t=this.matrixWorld.elements;return e.set(t[8],t[9],t[10]).normalize()}raycast(){}intersectsFrustum(){return!0}traverse(e){e(this);let t=this.children;for(let i=0,r=t.length;i<r;i++)t[i].traverse(e)}traverseVisible(e){if(this.visible===!1)return;e(this);let t=this.children;for(let i=0,r=t.length;i<r;i++)t[i].traverseVisible(e)}traverseAncestors(e){let t=this.parent;t!==null&&(e(t),t.traverseAncestors(e))}updateMatrix(){this.matrix.compose(this.position,this.quaternion,this.scale);let e=this.pivot;if(e!==null){let t=e.x,i=e.y,r=e.z,s=this.matrix.elements;s[12]+=t-s[0]*t-s[4]*i-s[8]*r,s[13]+=i-s[1]*t-s[5]*i-s[9]*r,s[14]+=r-s[2]*t-s[6]*i-s[10]*r}this.matrixWorldNeedsUpdate=!0}updateMatrixWorld(e){this.matrixAutoUpdate&&this.updateMatrix(),(this.matrixWorldNeedsUpdate||e)&&(this.matrixWorldAutoUpdate===!0&&(this.parent===null?this.matrixWorld.copy(this.matrix):this.matrixWorld.multiplyMatrices(this.parent.matrixWorld,this.matrix)),this.matrixWorldNeedsUpdate=!1,e=!0);let t=this.children;for(let i=0,r=t.length;i<r;i++)t[i].updateMatrixWorld(e)}updateWorldMatrix(e,t,i=!1){let r=this.parent;if(e===!0&&r!==null&&r.updateWorldMatrix(!0,!1),this.matrixAutoUpdate&&this.updateMatrix(),(this.matrixWorldNeedsUpdate||i)&&(this.matrixWorldAutoUpdate===!0&&(this.parent===null?this.matrixWorld.copy(this.matrix):this.matrixWorld.multiplyMatrices(this.parent.matrixWorld,this.matrix)),this.matrixWorldNeedsUpdate=!1,i=!0),t===!0){let s=this.children;for(let o=0,a=s.length;o<a;o++)s[o].updateWorldMatrix(!1,!0,i)}}toJSON(e){let t=e===void 0||typeof e=="string",i={};t&&(e={geometries:{},materials:{},textures:{},images:{},shapes:{},skeletons:{},animations:{},nodes:{}},i.metadata={version:4.7,type:"Object",generator:"Object3D.toJSON"});let r={};r.uuid=this.uuid,r.type=this.type,r.name=this.name,r.castShadow=this.castShadow,r.receiveShadow=this.receiveShadow,r.visible=this.visible,r.frustumCulled=this.frustumCulled,r.renderOrder=this.renderOrder,r.static=this.static,r.matrixAutoUpdate=this.matrixAutoUpdate,Object.keys(this.userData).length>0&&(r.userData=this.userData),r.layers=this.layers.mask,r.matrix=this.matrix.toArray(),r.up=this.up.toArray(),this.pivot!==null&&(r.pivot=this.pivot.toArray()),this.morphTargetDictionary!==void 0&&(r.morphTargetDictionary=Object.assign({},this.morphTargetDictionary)),this.morphTargetInfluences!==void 0&&(r.morphTargetInfluences=this.morphTargetInfluences.slice()),this.isInstancedMesh&&(r.type="InstancedMesh",r.count=this.count,r.instanceMatrix=this.instanceMatrix.toJSON(),this.instanceColor!==null&&(r.instanceColor=this.instanceColor.toJSON())),this.isBatchedMesh&&(r.type="BatchedMesh",r.perObjectFrustumCulled=this.perObjectFrustumCulled,r.sortObjects=this.sortObjects,r.drawRanges=this._drawRanges,r.reservedRanges=this._reservedRanges,r.geometryInfo=this._geometryInfo.map(a=>({...a,boundingBox:a.boundingBox?a.boundingBox.toJSON():void 0,boundingSphere:a.boundingSphere?a.boundingSphere.toJSON():void 0})),r.instanceInfo=this._instanceInfo.map(a=>({...a})),r.availableInstanceIds=this._availableInstanceIds.slice(),r.availableGeometryIds=this._availableGeometryIds.slice(),r.nextIndexStart=this._nextIndexStart,r.nextVertexStart=this._nextVertexStart,r.geometryCount=this._geometryCount,r.maxInstanceCount=this._maxInstanceCount,r.maxVertexCount=this._maxVertexCount,r.maxIndexCount=this._maxIndexCount,r.geometryInitialized=this._geometryInitialized,r.matricesTexture=this._matricesTexture.toJSON(e),r.indirectTexture=this._indirectTexture.toJSON(e),this._colorsTexture!==null&&(r.colorsTexture=this._colorsTexture.toJSON(e)),this.boundingSphere!==null&&(r.boundingSphere=this.boundingSphere.toJSON()),this.boundingBox!==null&&(r.boundingBox=this.boundingBox.toJSON()));function s(a,l){return a[l.uuid]===void 0&&(a[l.uuid]=l.toJSON(e)),l.uuid}if(this.isScene)this.background&&(this.background.isColor?r.background=this.background.toJSON():this.background.isTexture&&(r.background=this.background.toJSON(e).uuid)),this.environment&&this.environment.isTexture&&this.environment.isRenderTargetTexture!==!0&&(r.environment=this.environment.toJSON(e).uuid);else if(this.isMesh||this.isLine||this.isPoints){r.geometry=s(e.geometries,this.geometry);let a=this.geometry.parameters;if(a!==void 0&&a.shapes!==void 0){let l=a.shapes;if(Array.isArray(l))for(let c=0,u=l.length;c<u;c++){let h=l[c];s(e.shapes,h)}else s(e.shapes,l)}}if(this.isSkinnedMesh&&(r.bindMode=this.bindMode,r.bindMatrix=this.bindMatrix.toArray(),this.skeleton!==void 0&&(s(e.skeletons,this.skeleton),r.skeleton=this.skeleton.uuid)),this.material!==void 0)if(Array.isArray(this.material)){let a=[];for(let l=0,c=this.material.length;l<c;l++)a.push(s(e.materials,this.material[l]));r.material=a}else r.material=s(e.materials,this.material);if(this.children.length>0){r.children=[];for(let a=0;a<this.children.length;a++)r.children.push(this.children[a].toJSON(e).object)}if(this.animations.length>0){r.animations=[];for(let a=0;a<this.animations.length;a++){let l=this.animations[a];r.animations.push(s(e.animations,l))}}if(t){let a=o(e.geometries),l=o(e.materials),c=o(e.textures),u=o(e.images),h=o(e.shapes),f=o(e.skeletons),d=o(e.animations),p=o(e.nodes);a.length>0&&(i.geometries=a),l.length>0&&(i.materials=l),c.length>0&&(i.textures=c),u.length>0&&(i.images=u),h.length>0&&(i.shapes=h),f.length>0&&(i.skeletons=f),d.length>0&&(i.animations=d),p.length>0&&(i.nodes=p)}return i.object=r,i;function o(a){let l=[];for(let c in a){let u=a[c];delete u.metadata,l.push(u)}return l}}clone(e){return new this.constructor().copy(this,e)}copy(e,t=!0){if(this.name=e.name,this.up.copy(e.up),this.position.copy(e.position),this.rotation.order=e.rotation.order,this.quaternion.copy(e.quaternion),this.scale.copy(e.scale),this.pivot=e.pivot!==null?e.pivot.clone():null,this.matrix.copy(e.matrix),this.matrixWorld.copy(e.matrixWorld),this.matrixAutoUpdate=e.matrixAutoUpdate,this.matrixWorldAutoUpdate=e.matrixWorldAutoUpdate,this.matrixWorldNeedsUpdate=e.matrixWorldNeedsUpdate,this.layers.mask=e.layers.mask,this.visible=e.visible,this.castShadow=e.castShadow,this.receiveShadow=e.receiveShadow,this.frustumCulled=e.frustumCulled,this.renderOrder=e.renderOrder,this.static=e.static,this.animations=e.animations.slice(),this.userData=JSON.parse(JSON.stringify(e.userData)),t===!0)for(let i=0;i<e.children.length;i++){let r=e.children[i];this.add(r.clone())}return this}dispose(){this.dispatchEvent({type:"dispose"})}};Xn.DEFAULT_UP=new X(0,1,0);Xn.DEFAULT_MATRIX_AUTO_UPDATE=!0;Xn.DEFAULT_MATRIX_WORLD_AUTO_UPDATE=!0;var ks=class extends Xn{constructor(){super(),this.isGroup=!0,this.type="Group"}},MA={type:"move"},Ko=class{constructor(){this._targetRay=null,this._grip=null,this._hand=null}getHandSpace(){return this._hand===null&&(this._hand=new ks,this._hand.matrixAutoUpdate=!1,this._hand.visible=!1,this._hand.joints={},this._hand.inputState={pinching:!1}),this._hand}getTargetRaySpace(){return this._targetRay===null&&(this._targetRay=new ks,this._targetRay.matrixAutoUpdate=!1,this._targetRay.visible=!1,this._targetRay.hasLinearVelocity=!1,this._targetRay.linearVelocity=new X,this._targetRay.hasAngularVelocity=!1,this._targetRay.angularVelocity=new X),this._targetRay}getGripSpace(){return this._grip===null&&(this._grip=new ks,this._grip.matrixAutoUpdate=!1,this._grip.visible=!1,this._grip.hasLinearVelocity=!1,this._grip.linearVelocity=new X,this._grip.hasAngularVelocity=!1,this._grip.angularVelocity=new X,this._grip.eventsEnabled=!1),this._grip}dispatchEvent(e){return this._targetRay!==null&&this._targetRay.dispatchEvent(e),this._grip!==null&&this._grip.dispatchEvent(e),this._hand!==null&&this._hand.dispatchEvent(e),this}connect(e){if(e&&e.hand){let t=this._hand;if(t)for(let i of e.hand.values())this._getHandJoint(t,i)}return this.dispatchEvent({type:"connected",data:e}),this}disconnect(e){return this.dispatchEvent({type:"disconnected",data:e}),this._targetRay!==null&&(this._targetRay.visible=!1),this._grip!==null&&(this._grip.visible=!1),this._hand!==null&&(this._hand.visible=!1),this}update(e,t,i){let r=null,s=null,o=null,a=this._targetRay,l=this._grip,c=this._hand;if(e&&t.session.visibilityState!=="visible-blurred"){if(c&&e.hand){o=!0;for(let x of e.hand.values()){let m=t.getJointPose(x,i),g=this._getHandJoint(c,x);m!==null&&(g.matrix.fromArray(m.transform.matrix),g.matrix.decompose(g.position,g.quaternion,g.scale),g.matrixWorldNeedsUpdate=!0,g.jointRadius=m.radius),g.visible=m!==null}let u=c.joints["index-finger-tip"],h=c.joints["thumb-tip"],f=u.position.distanceTo(h.position),d=.02,p=.005;c.inputState.pinching&&f>d+p?(c.inputState.pinching=!1,this.dispatchEvent({type:"pinchend",handedness:e.handedness,target:this})):!c.inputState.pinching&&f<=d-p&&(c.inputState.pinching=!0,this.dispatchEvent({type:"pinchstart",handedness:e.handedness,target:this}))}else l!==null&&e.gripSpace&&(s=t.getPose(e.gripSpace,i),s!==null&&(l.matrix.fromArray(s.transform.matrix),l.matrix.decompose(l.position,l.quaternion,l.scale),l.matrixWorldNeedsUpdate=!0,s.linearVelocity?(l.hasLinearVelocity=!0,l.linearVelocity.copy(s.linearVelocity)):l.hasLinearVelocity=!1,s.angularVelocity?(l.hasAngularVelocity=!0,l.angularVelocity.copy(s.angularVelocity)):l.hasAngularVelocity=!1,l.eventsEnabled&&l.dispatchEvent({type:"gripUpdated",data:e,target:this})));a!==null&&(r=t.getPose(e.targetRaySpace,i),r===null&&s!==null&&(r=s),r!==null&&(a.matrix.fromArray(r.transform.matrix),a.matrix.decompose(a.position,a.quaternion,a.scale),a.matrixWorldNeedsUpdate=!0,r.linearVelocity?(a.hasLinearVelocity=!0,a.linearVelocity.copy(r.linearVelocity)):a.hasLinearVelocity=!1,r.angularVelocity?(a.hasAngularVelocity=!0,a.angularVelocity.copy(r.angularVelocity)):a.hasAngularVelocity=!1,this.dispatchEvent(MA)))}return a!==null&&(a.visible=r!==null),l!==null&&(l.visible=s!==null),c!==null&&(c.visible=o!==null),this}_getHandJoint(e,t){if(e.joints[t.jointName]===void 0){let i=new ks;i.matrixAutoUpdate=!1,i.visible=!1,e.joints[t.jointName]=i,e.add(i)}return e.joints[t.jointName]}},qb={aliceblue:15792383,antiquewhite:16444375,aqua:65535,aquamarine:8388564,azure:15794175,beige:16119260,bisque:16770244,black:0,blanchedalmond:16772045,blue:255,blueviolet:9055202,brown:10824234,burlywood:14596231,cadetblue:6266528,chartreuse:8388352,chocolate:13789470,coral:16744272,cornflowerblue:6591981,cornsilk:16775388,crimson:14423100,cyan:65535,darkblue:139,darkcyan:35723,darkgoldenrod:12092939,darkgray:11119017,darkgreen:25600,darkgrey:11119017,darkkhaki:12433259,darkmagenta:9109643,darkolivegreen:5597999,darkorange:16747520,darkorchid:10040012,darkred:9109504,darksalmon:15308410,darkseagreen:9419919,darkslateblue:4734347,darkslategray:3100495,darkslategrey:3100495,darkturquoise:52945,darkviolet:9699539,deeppink:16716947,deepskyblue:49151,dimgray:6908265,dimgrey:6908265,dodgerblue:2003199,firebrick:11674146,floralwhite:16775920,forestgreen:2263842,fuchsia:16711935,gainsboro:14474460,ghostwhite:16316671,gold:16766720,goldenrod:14329120,gray:8421504,green:32768,greenyellow:11403055,grey:8421504,honeydew:15794160,hotpink:16738740,indianred:13458524,indigo:4915330,ivory:16777200,khaki:15787660,lavender:15132410,lavenderblush:16773365,lawngreen:8190976,lemonchiffon:16775885,lightblue:11393254,lightcoral:15761536,lightcyan:14745599,lightgoldenrodyellow:16448210,lightgray:13882323,lightgreen:9498256,lightgrey:13882323,lightpink:16758465,lightsalmon:16752762,lightseagreen:2142890,lightskyblue:8900346,lightslategray:7833753,lightslategrey:7833753,lightsteelblue:11584734,lightyellow:16777184,lime:65280,limegreen:3329330,linen:16445670,magenta:16711935,maroon:8388608,mediumaquamarine:6737322,mediumblue:205,mediumorchid:12211667,mediumpurple:9662683,mediumseagreen:3978097,mediumslateblue:8087790,mediumspringgreen:64154,mediumturquoise:4772300,mediumvioletred:13047173,midnightblue:1644912,mintcream:16121850,mistyrose:16770273,moccasin:16770229,navajowhite:16768685,navy:128,oldlace:16643558,olive:8421376,olivedrab:7048739,orange:16753920,orangered:16729344,orchid:14315734,palegoldenrod:15657130,palegreen:10025880,paleturquoise:11529966,palevioletred:14381203,papayawhip:16773077,peachpuff:16767673,peru:13468991,pink:16761035,plum:14524637,powderblue:11591910,purple:8388736,rebeccapurple:6697881,red:16711680,rosybrown:12357519,royalblue:4286945,saddlebrown:9127187,salmon:16416882,sandybrown:16032864,seagreen:3050327,seashell:16774638,sienna:10506797,silver:12632256,skyblue:8900331,slateblue:6970061,slategray:7372944,slategrey:7372944,snow:16775930,springgreen:65407,steelblue:4620980,tan:13808780,teal:32896,thistle:14204888,tomato:16737095,turquoise:4251856,violet:15631086,wheat:16113331,white:16777215,whitesmoke:16119285,yellow:16776960,yellowgreen:10145074},os={h:0,s:0,l:0},jc={h:0,s:0,l:0};function pp(n,e,t){return t<0&&(t+=1),t>1&&(t-=1),t<1/6?n+(e-n)*6*t:t<1/2?e:t<2/3?n+(e-n)*6*(2/3-t):n}var tt=class{constructor(e,t,i){return this.isColor=!0,this.r=1,this.g=1,this.b=1,this.set(e,t,i)}set(e,t,i){if(t===void 0&&i===void 0){let r=e;r&&r.isColor?this.copy(r):typeof r=="number"?this.setHex(r):typeof r=="string"&&this.setStyle(r)}else this.setRGB(e,t,i);return this}setScalar(e){return this.r=e,this.g=e,this.b=e,this}setHex(e,t=Si){return e=Math.floor(e),this.r=(e>>16&255)/255,this.g=(e>>8&255)/255,this.b=(e&255)/255,St.colorSpaceToWorking(this,t),this}setRGB(e,t,i,r=St.workingColorSpace){return this.r=e,this.g=t,this.b=i,St.colorSpaceToWorking(this,r),this}setHSL(e,t,i,r=St.workingColorSpace){if(e=um(e,1),t=_t(t,0,1),i=_t(i,0,1),t===0)this.r=this.g=this.b=i;else{let s=i<=.5?i*(1+t):i+t-i*t,o=2*i-s;this.r=pp(o,s,e+1/3),this.g=pp(o,s,e),this.b=pp(o,s,e-1/3)}return St.colorSpaceToWorking(this,r),this}setStyle(e,t=Si){function i(s){s!==void 0&&parseFloat(s)<1&&$e("Color: Alpha component of "+e+" will be ignored.")}let r;if(r=/^(\w+)\(([^\)]*)\)/.exec(e)){let s,o=r[1],a=r[2];switch(o){case"rgb":case"rgba":if(s=/^\s*(\d+)\s*,\s*(\d+)\s*,\s*(\d+)\s*(?:,\s*(\d+(?:\.\d+)?|\.\d+)\s*)?$/.exec(a))return i(s[4]),this.setRGB(Math.min(255,parseInt(s[1],10))/255,Math.min(255,parseInt(s[2],10))/255,Math.min(255,parseInt(s[3],10))/255,t);if(s=/^\s*(\d+(?:\.\d+)?|\.\d+)\%\s*,\s*(\d+(?:\.\d+)?|\.\d+)\%\s*,\s*(\d+(?:\.\d+)?|\.\d+)\%\s*(?:,\s*(\d+(?:\.\d+)?|\.\d+)\s*)?$/.exec(a))return i(s[4]),this.setRGB(Math.min(100,parseFloat(s[1]))/100,Math.min(100,parseFloat(s[2]))/100,Math.min(100,parseFloat(s[3]))/100,t);break;case"hsl":case"hsla":if(s=/^\s*([+-]?(?:\d+(?:\.\d+)?|\.\d+))\s*,\s*(\d+(?:\.\d+)?|\.\d+)\%\s*,\s*(\d+(?:\.\d+)?|\.\d+)\%\s*(?:,\s*(\d+(?:\.\d+)?|\.\d+)\s*)?$/.exec(a))return i(s[4]),this.setHSL(parseFloat(s[1])/360,parseFloat(s[2])/100,parseFloat(s[3])/100,t);break;default:$e("Color: Unknown color model "+e)}}else if(r=/^\#([A-Fa-f\d]+)$/.exec(e)){let s=r[1],o=s.length;if(o===3)return this.setRGB(parseInt(s.charAt(0),16)/15,parseInt(s.charAt(1),16)/15,parseInt(s.charAt(2),16)/15,t);if(o===6)return this.setHex(parseInt(s,16),t);$e("Color: Invalid hex color "+e)}else if(e&&e.length>0)return this.setColorName(e,t);return this}setColorName(e,t=Si){let i=qb[e.toLowerCase()];return i!==void 0?this.setHex(i,t):$e("Color: Unknown color "+e),this}clone(){return new this.constructor(this.r,this.g,this.b)}copy(e){return this.r=e.r,this.g=e.g,this.b=e.b,this}copySRGBToLinear(e){return this.r=Br(e.r),this.g=Br(e.g),this.b=Br(e.b),this}copyLinearToSRGB(e){return this.r=Go(e.r),this.g=Go(e.g),this.b=Go(e.b),this}convertSRGBToLinear(){return this.copySRGBToLinear(this),this}convertLinearToSRGB(){return this.copyLinearToSRGB(this),this}getHex(e=Si){return St.workingToColorSpace($n.copy(this),e),Math.round(_t($n.r*255,0,255))*65536+Math.round(_t($n.g*255,0,255))*256+Math.round(_t($n.b*255,0,255))}getHexString(e=Si){return("000000"+this.getHex(e).toString(16)).slice(-6)}getHSL(e,t=St.workingColorSpace){St.workingToColorSpace($n.copy(this),t);let i=$n.r,r=$n.g,s=$n.b,o=Math.max(i,r,s),a=Math.min(i,r,s),l,c,u=(a+o)/2;if(a===o)l=0,c=0;else{let h=o-a;switch(c=u<=.5?h/(o+a):h/(2-o-a),o){case i:l=(r-s)/h+(r<s?6:0);break;case r:l=(s-i)/h+2;break;case s:l=(i-r)/h+4;break}l/=6}return e.h=l,e.s=c,e.l=u,e}getRGB(e,t=St.workingColorSpace){return St.workingToColorSpace($n.copy(this),t),e.r=$n.r,e.g=$n.g,e.b=$n.b,e}getStyle(e=Si){St.workingToColorSpace($n.copy(this),e);let t=$n.r,i=$n.g,r=$n.b;return e!==Si?`color(${e} ${t.toFixed(3)} ${i.toFixed(3)} ${r.toFixed(3)})`:`rgb(${Math.round(t*255)},${Math.round(i*255)},${Math.round(r*255)})`}offsetHSL(e,t,i){return this.getHSL(os),this.setHSL(os.h+e,os.s+t,os.l+i)}add(e){return this.r+=e.r,this.g+=e.g,this.b+=e.b,this}addColors(e,t){return this.r=e.r+t.r,this.g=e.g+t.g,this.b=e.b+t.b,this}addScalar(e){return this.r+=e,this.g+=e,this.b+=e,this}sub(e){return this.r=Math.max(0,this.r-e.r),this.g=Math.max(0,this.g-e.g),this.b=Math.max(0,this.b-e.b),this}multiply(e){return this.r*=e.r,this.g*=e.g,this.b*=e.b,this}multiplyScalar(e){return this.r*=e,this.g*=e,this.b*=e,this}lerp(e,t){return this.r+=(e.r-this.r)*t,this.g+=(e.g-this.g)*t,this.b+=(e.b-this.b)*t,this}lerpColors(e,t,i){return this.r=e.r+(t.r-e.r)*i,this.g=e.g+(t.g-e.g)*i,this.b=e.b+(t.b-e.b)*i,this}lerpHSL(e,t){this.getHSL(os),e.getHSL(jc);let i=el(os.h,jc.h,t),r=el(os.s,jc.s,t),s=el(os.l,jc.l,t);return this.setHSL(i,r,s),this}setFromVector3(e){return this.r=e.x,this.g=e.y,this.b=e.z,this}applyMatrix3(e){let t=this.r,i=this.g,r=this.b,s=e.elements;return this.r=s[0]*t+s[3]*i+s[6]*r,this.g=s[1]*t+s[4]*i+s[7]*r,this.b=s[2]*t+s[5]*i+s[8]*r,this}equals(e){return e.r===this.r&&e.g===this.g&&e.b===this.b}fromArray(e,t=0){return this.r=e[t],this.g=e[t+1],this.b=e[t+2],this}toArray(e=[],t=0){return e[t]=this.r,e[t+1]=this.g,e[t+2]=this.b,e}fromBufferAttribute(e,t){return this.r=e.getX(t),this.g=e.getY(t),this.b=e.getZ(t),this}toJSON(){return this.getHex()}*[Symbol.iterator](){yield this.r,yield this.g,yield this.b}},$n=new tt;tt.NAMES=qb;var ol=class extends Xn{constructor(){super(),this.isScene=!0,this.type="Scene",this.background=null,this.environment=null,this.fog=null,this.backgroundBlurriness=0,this.backgroundIntensity=1,this.backgroundRotation=new Ji,this.environmentIntensity=1,this.environmentRotation=new Ji,this.overrideMaterial=null,typeof __THREE_DEVTOOLS__<"u"&&__THREE_DEVTOOLS__.dispatchEvent(new CustomEvent("observe",{detail:this}))}copy(e,t){return super.copy(e,t),this.background=e.background!==null?e.background.clone():null,this.environment=e.environment!==null?e.environment.clone():null,this.fog=e.fog!==null?e.fog.clone():null,this.backgroundBlurriness=e.backgroundBlurriness,this.backgroundIntensity=e.backgroundIntensity,this.backgroundRotation.copy(e.backgroundRotation),this.environmentIntensity=e.environmentIntensity,this.environmentRotation.copy(e.environmentRotation),this.overrideMaterial=e.overrideMaterial!==null?e.overrideMaterial.clone():null,this.matrixAutoUpdate=e.matrixAutoUpdate,this}toJSON(e){let t=super.toJSON(e);return this.fog!==null&&(t.object.fog=this.fog.toJSON()),t.object.backgroundBlurriness=this.backgroundBlurriness,t.object.backgroundIntensity=this.backgroundIntensity,t.object.backgroundRotation=this.backgroundRotation.toArray(),t.object.environmentIntensity=this.environmentIntensity,t.object.environmentRotation=this.environmentRotation.toArray(),t}},Ki=new X,Lr=new X,mp=new X,Dr=new X,Co=new X,No=new X,Xx=new X,gp=new X,_p=new X,yp=new X,xp=new tn,bp=new tn,vp=new tn,Or=class n{constructor(e=new X,t=new X,i=new X){this.a=e,this.b=t,this.c=i}static getNormal(e,t,i,r){r.subVectors(i,t),Ki.subVectors(e,t),r.cross(Ki);let s=r.lengthSq();return s>0?r.multiplyScalar(1/Math.sqrt(s)):r.set(0,0,0)}static getBarycoord(e,t,i,r,s){Ki.subVectors(r,t),Lr.subVectors(i,t),mp.subVectors(e,t);let o=Ki.dot(Ki),a=Ki.dot(Lr),l=Ki.dot(mp),c=Lr.dot(Lr),u=Lr.dot(mp),h=o*c-a*a;if(h===0)return s.set(0,0,0),null;let f=1/h,d=(c*l-a*u)*f,p=(o*u-a*l)*f;return s.set(1-d-p,p,d)}static containsPoint(e,t,i,r){return this.getBarycoord(e,t,i,r,Dr)===null?!1:Dr.x>=0&&Dr.y>=0&&Dr.x+Dr.y<=1}static getInterpolation(e,t,i,r,s,o,a,l){return this.getBarycoord(e,t,i,r,Dr)===null?(l.x=0,l.y=0,"z"in l&&(l.z=0),"w"in l&&(l.w=0),null):(l.setScalar(0),l.addScaledVector(s,Dr.x),l.addScaledVector(o,Dr.y),l.addScaledVector(a,Dr.z),l)}static getInterpolatedAttribute(e,t,i,r,s,o){return xp.setScalar(0),bp.setScalar(0),vp.setScalar(0),xp.fromBufferAttribute(e,t),bp.fromBufferAttribute(e,i),vp.fromBufferAttribute(e,r),o.setScalar(0),o.addScaledVector(xp,s.x),o.addScaledVector(bp,s.y),o.addScaledVector(vp,s.z),o}static isFrontFacing(e,t,i,r){return Ki.subVectors(i,t),Lr.subVectors(e,t),Ki.cross(Lr).dot(r)<0}set(e,t,i){return this.a.copy(e),this.b.copy(t),this.c.copy(i),this}setFromPointsAndIndices(e,t,i,r){return this.a.copy(e[t]),this.b.copy(e[i]),this.c.copy(e[r]),this}setFromAttributeAndIndices(e,t,i,r){return this.a.fromBufferAttribute(e,t),this.b.fromBufferAttribute(e,i),this.c.fromBufferAttribute(e,r),this}clone(){return new this.constructor().copy(this)}copy(e){return this.a.copy(e.a),this.b.copy(e.b),this.c.copy(e.c),this}getArea(){return Ki.subVectors(this.c,this.b),Lr.subVectors(this.a,this.b),Ki.cross(Lr).length()*.5}getMidpoint(e){return e.addVectors(this.a,this.b).add(this.c).multiplyScalar(1/3)}getNormal(e){return n.getNormal(this.a,this.b,this.c,e)}getPlane(e){return e.setFromCoplanarPoints(this.a,this.b,this.c)}getBarycoord(e,t){return n.getBarycoord(e,this.a,this.b,this.c,t)}getInterpolation(e,t,i,r,s){return n.getInterpolation(e,this.a,this.b,this.c,t,i,r,s)}containsPoint(e){return n.containsPoint(e,this.a,this.b,this.c)}isFrontFacing(e){return n.isFrontFacing(this.a,this.b,this.c,e)}intersectsBox(e){return e.intersectsTriangle(this)}closestPointToPoint(e,t){let i=this.a,r=this.b,s=this.c,o,a;Co.subVectors(r,i),No.subVectors(s,i),gp.subVectors(e,i);let l=Co.dot(gp),c=No.dot(gp);if(l<=0&&c<=0)return t.copy(i);_p.subVectors(e,r);let u=Co.dot(_p),h=No.dot(_p);if(u>=0&&h<=u)return t.copy(r);let f=l*h-u*c;if(f<=0&&l>=0&&u<=0&&l-u>0)return o=l/(l-u),t.copy(i).addScaledVector(Co,o);yp.subVectors(e,s);let d=Co.dot(yp),p=No.dot(yp);if(p>=0&&d<=p)return t.copy(s);let x=d*c-l*p;if(x<=0&&c>=0&&p<=0)return a=c/(c-p),t.copy(i).addScaledVector(No,a);let m=u*p-d*h;if(m<=0&&h-u>=0&&d-p>=0)return Xx.subVectors(s,r),a=(h-u)/(h-u+(d-p)),t.copy(r).addScaledVector(Xx,a);let g=1/(m+x+f);return o=x*g,a=f*g,t.copy(i).addScaledVector(Co,o).addScaledVector(No,a)}equals(e){return e.a.equals(this.a)&&e.b.equals(this.b)&&e.c.equals(this.c)}},gr=class{constructor(e=new X(1/0,1/0,1/0),t=new X(-1/0,-1/0,-1/0)){this.isBox3=!0,this.min=e,this.max=t}set(e,t){return this.min.copy(e),this.max.copy(t),this}setFromArray(e){this.makeEmpty();for(let t=0,i=e.length;t<i;t+=3)this.expandByPoint($i.fromArray(e,t));return this}setFromBufferAttribute(e){this.makeEmpty();for(let t=0,i=e.count;t<i;t++)this.expandByPoint($i.fromBufferAttribute(e,t));return this}setFromPoints(e){this.makeEmpty();for(let t=0,i=e.length;t<i;t++)this.expandByPoint(e[t]);return this}setFromCenterAndSize(e,t){let i=$i.copy(t).multiplyScalar(.5);return this.min.copy(e).sub(i),this.max.copy(e).add(i),this}setFromObject(e,t=!1){return this.makeEmpty(),this.expandByObject(e,t)}clone(){return new this.constructor().copy(this)}copy(e){return this.min.copy(e.min),this.max.copy(e.max),this}makeEmpty(){return this.min.x=this.min.y=this.min.z=1/0,this.max.x=this.max.y=this.max.z=-1/0,this}isEmpty(){return this.max.x<this.min.x||this.max.y<this.min.y||this.max.z<this.min.z}getCenter(e){return this.isEmpty()?e.set(0,0,0):e.addVectors(this.min,this.max).multiplyScalar(.5)}getSize(e){return this.isEmpty()?e.set(0,0,0):e.subVectors(this.max,this.min)}expandByPoint(e){return this.min.min(e),this.max.max(e),this}expandByVector(e){return this.min.sub(e),this.max.add(e),this}expandByScalar(e){return this.min.addScalar(-e),this.max.addScalar(e),this}expandByObject(e,t=!1){e.updateWorldMatrix(!1,!1);let i=e.geometry;if(i!==void 0){let s=i.getAttribute("position");if(t===!0&&s!==void 0&&e.isInstancedMesh!==!0&&e.isBatchedMesh!==!0)for(let o=0,a=s.count;o<a;o++)e.isMesh===!0?e.getVertexPosition(o,$i):$i.fromBufferAttribute(s,o),$i.applyMatrix4(e.matrixWorld),this.expandByPoint($i);else e.boundingBox!==void 0?(e.boundingBox===null&&e.computeBoundingBox(),Qc.copy(e.boundingBox)):(i.boundingBox===null&&i.computeBoundingBox(),Qc.copy(i.boundingBox)),Qc.applyMatrix4(e.matrixWorld),this.union(Qc)}let r=e.children;for(let s=0,o=r.length;s<o;s++)this.expandByObject(r[s],t);return this}containsPoint(e){return e.x>=this.min.x&&e.x<=this.max.x&&e.y>=this.min.y&&e.y<=this.max.y&&e.z>=this.min.z&&e.z<=this.max.z}containsBox(e){return this.min.x<=e.min.x&&e.max.x<=this.max.x&&this.min.y<=e.min.y&&e.max.y<=this.max.y&&this.min.z<=e.min.z&&e.max.z<=this.max.z}getParameter(e,t){return t.set((e.x-this.min.x)/(this.max.x-this.min.x),(e.y-this.min.y)/(this.max.y-this.min.y),(e.z-this.min.z)/(this.max.z-this.min.z))}intersectsBox(e){return e.max.x>=this.min.x&&e.min.x<=this.max.x&&e.max.y>=this.min.y&&e.min.y<=this.max.y&&e.max.z>=this.min.z&&e.min.z<=this.max.z}intersectsSphere(e){return this.clampPoint(e.center,$i),$i.distanceToSquared(e.center)<=e.radius*e.radius}intersectsPlane(e){let t,i;return e.normal.x>0?(t=e.normal.x*this.min.x,i=e.normal.x*this.max.x):(t=e.normal.x*this.max.x,i=e.normal.x*this.min.x),e.normal.y>0?(t+=e.normal.y*this.min.y,i+=e.normal.y*this.max.y):(t+=e.normal.y*this.max.y,i+=e.normal.y*this.min.y),e.normal.z>0?(t+=e.normal.z*this.min.z,i+=e.normal.z*this.max.z):(t+=e.normal.z*this.max.z,i+=e.normal.z*this.min.z),t<=-e.constant&&i>=-e.constant}intersectsTriangle(e){if(this.isEmpty())return!1;this.getCenter(Za),eu.subVectors(this.max,Za),Po.subVectors(e.a,Za),Lo.subVectors(e.b,Za),Do.subVectors(e.c,Za),as.subVectors(Lo,Po),ls.subVectors(Do,Lo),Fs.subVectors(Po,Do);let t=[0,-as.z,as.y,0,-ls.z,ls.y,0,-Fs.z,Fs.y,as.z,0,-as.x,ls.z,0,-ls.x,Fs.z,0,-Fs.x,-as.y,as.x,0,-ls.y,ls.x,0,-Fs.y,Fs.x,0];return!Sp(t,Po,Lo,Do,eu)||(t=[1,0,0,0,1,0,0,0,1],!Sp(t,Po,Lo,Do,eu))?!1:(tu.crossVectors(as,ls),t=[tu.x,tu.y,tu.z],Sp(t,Po,Lo,Do,eu))}clampPoint(e,t){return t.copy(e).clamp(this.min,this.max)}distanceToPoint(e){return this.clampPoint(e,$i).distanceTo(e)}getBoundingSphere(e){return this.isEmpty()?e.makeEmpty():(this.getCenter(e.center),e.radius=this.getSize($i).length()*.5),e}intersect(e){return this.min.max(e.min),this.max.min(e.max),this.isEmpty()&&this.makeEmpty(),this}union(e){return this.min.min(e.min),this.max.max(e.max),this}applyMatrix4(e){return this.isEmpty()?this:(Fr[0].set(this.min.x,this.min.y,this.min.z).applyMatrix4(e),Fr[1].set(this.min.x,this.min.y,this.max.z).applyMatrix4(e),Fr[2].set(this.min.x,this.max.y,this.min.z).applyMatrix4(e),Fr[3].set(this.min.x,this.max.y,this.max.z).applyMatrix4(e),Fr[4].set(this.max.x,this.min.y,this.min.z).applyMatrix4(e),Fr[5].set(this.max.x,this.min.y,this.max.z).applyMatrix4(e),Fr[6].set(this.max.x,this.max.y,this.min.z).applyMatrix4(e),Fr[7].set(this.max.x,this.max.y,this.max.z).applyMatrix4(e),this.setFromPoints(Fr),this)}translate(e){return this.min.add(e),this.max.add(e),this}equals(e){return e.min.equals(this.min)&&e.max.equals(this.max)}toJSON(){return{min:this.min.toArray(),max:this.max.toArray()}}fromJSON(e){return this.min.fromArray(e.min),this.max.fromArray(e.max),this}},Fr=[new X,new X,new X,new X,new X,new X,new X,new X],$i=new X,Qc=new gr,Po=new X,Lo=new X,Do=new X,as=new X,ls=new X,Fs=new X,Za=new X,eu=new X,tu=new X,Us=new X;function Sp(n,e,t,i,r){for(let s=0,o=n.length-3;s<=o;s+=3){Us.fromArray(n,s);let a=r.x*Math.abs(Us.x)+r.y*Math.abs(Us.y)+r.z*Math.abs(Us.z),l=e.dot(Us),c=t.dot(Us),u=i.dot(Us);if(Math.max(-Math.max(l,c,u),Math.min(l,c,u))>a)return!1}return!0}var En=new X,nu=new Ke,wA=0,kn=class extends qi{constructor(e,t,i=!1){if(super(),Array.isArray(e))throw new TypeError("THREE.BufferAttribute: array should be a Typed Array.");this.isBufferAttribute=!0,Object.defineProperty(this,"id",{value:wA++}),this.name="",this.array=e,this.itemSize=t,this.count=e!==void 0?e.length/t:0,this.normalized=i,this.usage=Hb,this.updateRanges=[],this.gpuType=Ui,this.version=0,this._normalizationScale=e!==void 0?fm(e):void 0}onUploadCallback(){}set needsUpdate(e){e===!0&&this.version++}setUsage(e){return this.usage=e,this}addUpdateRange(e,t){this.updateRanges.push({start:e,count:t})}clearUpdateRanges(){this.updateRanges.length=0}copy(e){return this.name=e.name,this.array=new e.array.constructor(e.array),this.itemSize=e.itemSize,this.count=e.count,this.normalized=e.normalized,this.usage=e.usage,this.gpuType=e.gpuType,this._normalizationScale=e._normalizationScale,this}copyAt(e,t,i){e*=this.itemSize,i*=t.itemSize;for(let r=0,s=this.itemSize;r<s;r++)this.array[e+r]=t.array[i+r];return this}copyArray(e){return this.array.set(e),this}applyMatrix3(e){if(this.itemSize===2)for(let t=0,i=this.count;t<i;t++)nu.fromBufferAttribute(this,t),nu.applyMatrix3(e),this.setXY(t,nu.x,nu.y);else if(this.itemSize===3)for(let t=0,i=this.count;t<i;t++)En.fromBufferAttribute(this,t),En.applyMatrix3(e),this.setXYZ(t,En.x,En.y,En.z);return this}applyMatrix4(e){for(let t=0,i=this.count;t<i;t++)En.fromBufferAttribute(this,t),En.applyMatrix4(e),this.setXYZ(t,En.x,En.y,En.z);return this}applyNormalMatrix(e){for(let t=0,i=this.count;t<i;t++)En.fromBufferAttribute(this,t),En.applyNormalMatrix(e),this.setXYZ(t,En.x,En.y,En.z);return this}transformDirection(e){for(let t=0,i=this.count;t<i;t++)En.fromBufferAttribute(this,t),En.transformDirection(e),this.setXYZ(t,En.x,En.y,En.z);return this}set(e,t=0){return this.array.set(e,t),this}getComponent(e,t){let i=this.array[e*this.itemSize+t];return this.normalized&&(i=this._denormalize(i)),i}setComponent(e,t,i){return this.normalized&&(i=this._normalize(i)),this.array[e*this.itemSize+t]=i,this}getX(e){let t=this.array[e*this.itemSize];return this.normalized&&(t=this._denormalize(t)),t}setX(e,t){return this.normalized&&(t=this._normalize(t)),this.array[e*this.itemSize]=t,this}getY(e){let t=this.array[e*this.itemSize+1];return this.normalized&&(t=this._denormalize(t)),t}setY(e,t){return this.normalized&&(t=this._normalize(t)),this.array[e*this.itemSize+1]=t,this}getZ(e){let t=this.array[e*this.itemSize+2];return this.normalized&&(t=this._denormalize(t)),t}setZ(e,t){return this.normalized&&(t=this._normalize(t)),this.array[e*this.itemSize+2]=t,this}getW(e){let t=this.array[e*this.itemSize+3];return this.normalized&&(t=this._denormalize(t)),t}setW(e,t){return this.normalized&&(t=this._normalize(t)),this.array[e*this.itemSize+3]=t,this}setXY(e,t,i){return e*=this.itemSize,this.normalized&&(t=this._normalize(t),i=this._normalize(i)),this.array[e+0]=t,this.array[e+1]=i,this}setXYZ(e,t,i,r){return e*=this.itemSize,this.normalized&&(t=this._normalize(t),i=this._normalize(i),r=this._normalize(r)),this.array[e+0]=t,this.array[e+1]=i,this.array[e+2]=r,this}setXYZW(e,t,i,r,s){return e*=this.itemSize,this.normalized&&(t=this._normalize(t),i=this._normalize(i),r=this._normalize(r),s=this._normalize(s)),this.array[e+0]=t,this.array[e+1]=i,this.array[e+2]=r,this.array[e+3]=s,this}onUpload(e){return this.onUploadCallback=e,this}clone(){return new this.constructor(this.array,this.itemSize).copy(this)}toJSON(){let e={itemSize:this.itemSize,type:this.array.constructor.name,array:Array.from(this.array),normalized:this.normalized};return e.name=this.name,e.usage=this.usage,e.gpuType=this.gpuType,e}dispose(){this.dispatchEvent({type:"dispose"})}_denormalize(e){let t=this._normalizationScale;return t!==void 0?Math.max(e/t,-1):Kb(e,this.array)}_normalize(e){let t=this._normalizationScale;return t!==void 0?Math.round(e*t):$b(e,this.array)}};var al=class extends kn{constructor(e,t,i){super(new Uint16Array(e),t,i)}};var ll=class extends kn{constructor(e,t,i){super(new Uint32Array(e),t,i)}};var jt=class extends kn{constructor(e,t,i){super(new Float32Array(e),t,i)}},TA=new gr,Ka=new X,Ep=new X,Vr=class{constructor(e=new X,t=-1){this.isSphere=!0,this.center=e,this.radius=t}set(e,t){return this.center.copy(e),this.radius=t,this}setFromPoints(e,t){let i=this.center;t!==void 0?i.copy(t):TA.setFromPoints(e).getCenter(i);let r=0;for(let s=0,o=e.length;s<o;s++)r=Math.max(r,i.distanceToSquared(e[s]));return this.radius=Math.sqrt(r),this}copy(e){return this.center.copy(e.center),this.radius=e.radius,this}isEmpty(){return this.radius<0}makeEmpty(){return this.center.set(0,0,0),this.radius=-1,this}containsPoint(e){return e.distanceToSquared(this.center)<=this.radius*this.radius}distanceToPoint(e){return e.distanceTo(this.center)-this.radius}intersectsSphere(e){let t=this.radius+e.radius;return e.center.distanceToSquared(this.center)<=t*t}intersectsBox(e){return e.intersectsSphere(this)}intersectsPlane(e){return Math.abs(e.distanceToPoint(this.center))<=this.radius}clampPoint(e,t){let i=this.center.distanceToSquared(e);return t.copy(e),i>this.radius*this.radius&&(t.sub(this.center).normalize(),t.multiplyScalar(this.radius).add(this.center)),t}getBoundingBox(e){return this.isEmpty()?(e.makeEmpty(),e):(e.set(this.center,this.center),e.expandByScalar(this.radius),e)}applyMatrix4(e){return this.center.applyMatrix4(e),this.radius=this.radius*e.getMaxScaleOnAxis(),this}translate(e){return this.center.add(e),this}expandByPoint(e){if(this.isEmpty())return this.center.copy(e),this.radius=0,this;Ka.subVectors(e,this.center);let t=Ka.lengthSq();if(t>this.radius*this.radius){let i=Math.sqrt(t),r=(i-this.radius)*.5;this.center.addScaledVector(Ka,r/i),this.radius+=r}return this}union(e){return e.isEmpty()?this:this.isEmpty()?(this.copy(e),this):(this.center.equals(e.center)===!0?this.radius=Math.max(this.radius,e.radius):(Ep.subVectors(e.center,this.center).setLength(e.radius),this.expandByPoint(Ka.copy(e.center).add(Ep)),this.expandByPoint(Ka.copy(e.center).sub(Ep))),this)}equals(e){return e.center.equals(this.center)&&e.radius===this.radius}clone(){return new this.constructor().copy(this)}toJSON(){return{radius:this.radius,center:this.center.toArray()}}fromJSON(e){return this.radius=e.radius,this.center.fromArray(e.center),this}},AA=0,Li=new Tt,Mp=new Xn,Fo=new X,vi=new gr,$a=new gr,Bn=new X,Gn=class n extends qi{constructor(){super(),this.isBufferGeometry=!0,Object.defineProperty(this,"id",{value:AA++}),this.uuid=ra(),this.name="",this.type="BufferGeometry",this.index=null,this.indirect=null,this.indirectOffset=0,this.attributes={},this.morphAttributes={},this.morphTargetsRelative=!1,this.groups=[],this.boundingBox=null,this.boundingSphere=null,this.drawRange={start:0,count:1/0},this.userData={},this._transformed=!1}getIndex(){return this.index}setIndex(e){return Array.isArray(e)?this.index=new(jT(e)?ll:al)(e,1):this.index=e,this}setIndirect(e,t=0){return this.indirect=e,this.indirectOffset=t,this}getIndirect(){return this.indirect}getAttribute(e){return this.attributes[e]}setAttribute(e,t){return this.attributes[e]=t,this}deleteAttribute(e){return delete this.attributes[e],this}hasAttribute(e){return this.attributes[e]!==void 0}addGroup(e,t,i=0){this.groups.push({start:e,count:t,materialIndex:i})}clearGroups(){this.groups=[]}setDrawRange(e,t){this.drawRange.start=e,this.drawRange.count=t}applyMatrix4(e){let t=this.attributes.position;t!==void 0&&(t.applyMatrix4(e),t.needsUpdate=!0);let i=this.attributes.normal;if(i!==void 0){let s=new it().getNormalMatrix(e);i.applyNormalMatrix(s),i.needsUpdate=!0}let r=this.attributes.tangent;return r!==void 0&&(r.transformDirection(e),r.needsUpdate=!0),this.boundingBox!==null&&this.computeBoundingBox(),this.boundingSphere!==null&&this.computeBoundingSphere(),this._transformed=!0,this}applyQuaternion(e){return Li.makeRotationFromQuaternion(e),this.applyMatrix4(Li),this}rotateX(e){return Li.makeRotationX(e),this.applyMatrix4(Li),this}rotateY(e){return Li.makeRotationY(e),this.applyMatrix4(Li),this}rotateZ(e){return Li.makeRotationZ(e),this.applyMatrix4(Li),this}translate(e,t,i){return Li.makeTranslation(e,t,i),this.applyMatrix4(Li),this}scale(e,t,i){return Li.makeScale(e,t,i),this.applyMatrix4(Li),this}lookAt(e){return Mp.lookAt(e),Mp.updateMatrix(),this.applyMatrix4(Mp.matrix),this}center(){return this.computeBoundingBox(),this.boundingBox.getCenter(Fo).negate(),this.translate(Fo.x,Fo.y,Fo.z),this}setFromPoints(e){let t=this.getAttribute("position");if(t===void 0){let i=[];for(let r=0,s=e.length;r<s;r++){let o=e[r];i.push(o.x,o.y,o.z||0)}this.setAttribute("position",new jt(i,3))}else{let i=Math.min(e.length,t.count);for(let r=0;r<i;r++){let s=e[r];t.setXYZ(r,s.x,s.y,s.z||0)}e.length>t.count&&$e("BufferGeometry: Buffer size too small for points data. Use .dispose() and create a new geometry."),t.needsUpdate=!0}return this}computeBoundingBox(){this.boundingBox===null&&(this.boundingBox=new gr);let e=this.attributes.position,t=this.morphAttributes.position;if(e&&e.isGLBufferAttribute){et("BufferGeometry.computeBoundingBox(): GLBufferAttribute requires a manual bounding box.",this),this.boundingBox.set(new X(-1/0,-1/0,-1/0),new X(1/0,1/0,1/0));return}if(e!==void 0){if(this.boundingBox.setFromBufferAttribute(e),t)for(let i=0,r=t.length;i<r;i++){let s=t[i];vi.setFromBufferAttribute(s),this.morphTargetsRelative?(Bn.addVectors(this.boundingBox.min,vi.min),this.boundingBox.expandByPoint(Bn),Bn.addVectors(this.boundingBox.max,vi.max),this.boundingBox.expandByPoint(Bn)):(this.boundingBox.expandByPoint(vi.min),this.boundingBox.expandByPoint(vi.max))}}else this.boundingBox.makeEmpty();(isNaN(this.boundingBox.min.x)||isNaN(this.boundingBox.min.y)||isNaN(this.boundingBox.min.z))&&et('BufferGeometry.computeBoundingBox(): Computed min/max have NaN values. The "position" attribute is likely to have NaN values.',this)}computeBoundingSphere(){this.boundingSphere===null&&(this.boundingSphere=new Vr);let e=this.attributes.position,t=this.morphAttributes.position;if(e&&e.isGLBufferAttribute){et("BufferGeometry.computeBoundingSphere(): GLBufferAttribute requires a manual bounding sphere.",this),this.boundingSphere.set(new X,1/0);return}if(e){let i=this.boundingSphere.center;if(vi.setFromBufferAttribute(e),t)for(let s=0,o=t.length;s<o;s++){let a=t[s];$a.setFromBufferAttribute(a),this.morphTargetsRelative?(Bn.addVectors(vi.min,$a.min),vi.expandByPoint(Bn),Bn.addVectors(vi.max,$a.max),vi.expandByPoint(Bn)):(vi.expandByPoint($a.min),vi.expandByPoint($a.max))}vi.getCenter(i);let r=0;for(let s=0,o=e.count;s<o;s++)Bn.fromBufferAttribute(e,s),r=Math.max(r,i.distanceToSquared(Bn));if(t)for(let s=0,o=t.length;s<o;s++){let a=t[s],l=this.morphTargetsRelative;for(let c=0,u=a.count;c<u;c++)Bn.fromBufferAttribute(a,c),l&&(Fo.fromBufferAttribute(e,c),Bn.add(Fo)),r=Math.max(r,i.distanceToSquared(Bn))}this.boundingSphere.radius=Math.sqrt(r),isNaN(this.boundingSphere.radius)&&et('BufferGeometry.computeBoundingSphere(): Computed radius is NaN. The "position" attribute is likely to have NaN values.',this)}}computeTangents(){let e=this.index,t=this.attributes;if(e===null||t.position===void 0||t.normal===void 0||t.uv===void 0){et("BufferGeometry: .computeTangents() failed. Missing required attributes (index, position, normal or uv)");return}let i=t.position,r=t.normal,s=t.uv,o=this.getAttribute("tangent");(o===void 0||o.count!==i.count)&&(o=new kn(new Float32Array(4*i.count),4),this.setAttribute("tangent",o));let a=[],l=[],c=new Uint8Array(i.count);for(let F=0;F<i.count;F++)a[F]=new X,l[F]=new X;let u=new X,h=new X,f=new X,d=new Ke,p=new Ke,x=new Ke,m=new X,g=new X;function b(F,N,P){c[F]=c[N]=c[P]=1,u.fromBufferAttribute(i,F),h.fromBufferAttribute(i,N),f.fromBufferAttribute(i,P),d.fromBufferAttribute(s,F),p.fromBufferAttribute(s,N),x.fromBufferAttribute(s,P),h.sub(u),f.sub(u),p.sub(d),x.sub(d);let k=1/(p.x*x.y-x.x*p.y);isFinite(k)&&(m.copy(h).multiplyScalar(x.y).addScaledVector(f,-p.y).multiplyScalar(k),g.copy(f).multiplyScalar(p.x).addScaledVector(h,-x.x).multiplyScalar(k),a[F].add(m),a[N].add(m),a[P].add(m),l[F].add(g),l[N].add(g),l[P].add(g))}let T=this.groups;T.length===0&&(T=[{start:0,count:e.count}]);for(let F=0,N=T.length;F<N;++F){let P=T[F],k=P.start,H=P.count;for(let D=k,W=k+H;D<W;D+=3)b(e.getX(D+0),e.getX(D+1),e.getX(D+2))}let v=new X,R=new X,A=new X,_=new X;function E(F){A.fromBufferAttribute(r,F),_.copy(A);let N=a[F];v.copy(N),v.sub(A.multiplyScalar(A.dot(N))).normalize(),R.crossVectors(_,N);let k=R.dot(l[F])<0?-1:1;o.setXYZW(F,v.x,v.y,v.z,k)}for(let F=0,N=i.count;F<N;++F)c[F]&&E(F);this._transformed=!0}computeVertexNormals(){let e=this.index,t=this.getAttribute("position");if(t!==void 0){let i=this.getAttribute("normal");if(i===void 0||i.count!==t.count)i=new kn(new Float32Array(t.count*3),3),this.setAttribute("normal",i);else for(let f=0,d=i.count;f<d;f++)i.setXYZ(f,0,0,0);let r=new X,s=new X,o=new X,a=new X,l=new X,c=new X,u=new X,h=new X;if(e)for(let f=0,d=e.count;f<d;f+=3){let p=e.getX(f+0),x=e.getX(f+1),m=e.getX(f+2);r.fromBufferAttribute(t,p),s.fromBufferAttribute(t,x),o.fromBufferAttribute(t,m),u.subVectors(o,s),h.subVectors(r,s),u.cross(h),a.fromBufferAttribute(i,p),l.fromBufferAttribute(i,x),c.fromBufferAttribute(i,m),a.add(u),l.add(u),c.add(u),i.setXYZ(p,a.x,a.y,a.z),i.setXYZ(x,l.x,l.y,l.z),i.setXYZ(m,c.x,c.y,c.z)}else for(let f=0,d=t.count;f<d;f+=3)r.fromBufferAttribute(t,f+0),s.fromBufferAttribute(t,f+1),o.fromBufferAttribute(t,f+2),u.subVectors(o,s),h.subVectors(r,s),u.cross(h),i.setXYZ(f+0,u.x,u.y,u.z),i.setXYZ(f+1,u.x,u.y,u.z),i.setXYZ(f+2,u.x,u.y,u.z);this.normalizeNormals(),i.needsUpdate=!0}}normalizeNormals(){let e=this.attributes.normal;for(let t=0,i=e.count;t<i;t++)Bn.fromBufferAttribute(e,t),Bn.normalize(),e.setXYZ(t,Bn.x,Bn.y,Bn.z)}toNonIndexed(){function e(a,l){let c=a.array,u=a.itemSize,h=a.normalized,f=new c.constructor(l.length*u),d=0,p=0;for(let x=0,m=l.length;x<m;x++){a.isInterleavedBufferAttribute?d=l[x]*a.data.stride+a.offset:d=l[x]*u;for(let g=0;g<u;g++)f[p++]=c[d++]}return new kn(f,u,h)}if(this.index===null)return $e("BufferGeometry.toNonIndexed(): BufferGeometry is already non-indexed."),this;let t=new n,i=this.index.array,r=this.attributes;for(let a in r){let l=r[a],c=e(l,i);t.setAttribute(a,c)}let s=this.morphAttributes;for(let a in s){let l=[],c=s[a];for(let u=0,h=c.length;u<h;u++){let f=c[u],d=e(f,i);l.push(d)}t.morphAttributes[a]=l}t.morphTargetsRelative=this.morphTargetsRelative;let o=this.groups;for(let a=0,l=o.length;a<l;a++){let c=o[a];t.addGroup(c.start,c.count,c.materialIndex)}return t}toJSON(){let e={metadata:{version:4.7,type:"BufferGeometry",generator:"BufferGeometry.toJSON"}};if(e.uuid=this.uuid,e.type=this.parameters!==void 0&&this._transformed===!0?"BufferGeometry":this.type,e.name=this.name,Object.keys(this.userData).length>0&&(e.userData=this.userData),this.parameters!==void 0&&this._transformed!==!0){let l=this.parameters;for(let c in l)l[c]!==void 0&&(e[c]=l[c]);return e}e.data={attributes:{}};let t=this.index;t!==null&&(e.data.index={type:t.array.constructor.name,array:Array.prototype.slice.call(t.array)});let i=this.attributes;for(let l in i){let c=i[l];e.data.attributes[l]=c.toJSON(e.data)}let r={},s=!1;for(let l in this.morphAttributes){let c=this.morphAttributes[l],u=[];for(let h=0,f=c.length;h<f;h++){let d=c[h];u.push(d.toJSON(e.data))}u.length>0&&(r[l]=u,s=!0)}s&&(e.data.morphAttributes=r,e.data.morphTargetsRelative=this.morphTargetsRelative);let o=this.groups;o.length>0&&(e.data.groups=JSON.parse(JSON.stringify(o)));let a=this.boundingSphere;return a!==null&&(e.data.boundingSphere=a.toJSON()),e}clone(){return new this.constructor().copy(this)}copy(e){this.index=null,this.attributes={},this.morphAttributes={},this.groups=[],this.boundingBox=null,this.boundingSphere=null;let t={};this.name=e.name;let i=e.index;i!==null&&this.setIndex(i.clone());let r=e.attributes;for(let c in r){let u=r[c];this.setAttribute(c,u.clone(t))}let s=e.morphAttributes;for(let c in s){let u=[],h=s[c];for(let f=0,d=h.length;f<d;f++)u.push(h[f].clone(t));this.morphAttributes[c]=u}this.morphTargetsRelative=e.morphTargetsRelative;let o=e.groups;for(let c=0,u=o.length;c<u;c++){let h=o[c];this.addGroup(h.start,h.count,h.materialIndex)}let a=e.boundingBox;a!==null&&(this.boundingBox=a.clone());let l=e.boundingSphere;return l!==null&&(this.boundingSphere=l.clone()),this.drawRange.start=e.drawRange.start,this.drawRange.count=e.drawRange.count,this.userData=e.userData,this._transformed=e._transformed,this}dispose(){this.dispatchEvent({type:"dispose"})}};var wp=new X,RA=new X,IA=new it,Ei=class{constructor(e=new X(1,0,0),t=0){this.isPlane=!0,this.normal=e,this.constant=t}set(e,t){return this.normal.copy(e),this.constant=t,this}setComponents(e,t,i,r){return this.normal.set(e,t,i),this.constant=r,this}setFromNormalAndCoplanarPoint(e,t){return this.normal.copy(e),this.constant=-t.dot(this.normal),this}setFromCoplanarPoints(e,t,i){let r=wp.subVectors(i,t).cross(RA.subVectors(e,t)).normalize();return this.setFromNormalAndCoplanarPoint(r,e),this}copy(e){return this.normal.copy(e.normal),this.constant=e.constant,this}normalize(){let e=1/this.normal.length();return this.normal.multiplyScalar(e),this.constant*=e,this}negate(){return this.constant*=-1,this.normal.negate(),this}distanceToPoint(e){return this.normal.dot(e)+this.constant}distanceToSphere(e){return this.distanceToPoint(e.center)-e.radius}projectPoint(e,t){return t.copy(e).addScaledVector(this.normal,-this.distanceToPoint(e))}intersectLine(e,t,i=!0){let r=e.delta(wp),s=this.normal.dot(r);if(s===0)return this.distanceToPoint(e.start)===0?t.copy(e.start):null;let o=-(e.start.dot(this.normal)+this.constant)/s;return i===!0&&(o<0||o>1)?null:t.copy(e.start).addScaledVector(r,o)}intersectsLine(e){let t=this.distanceToPoint(e.start),i=this.distanceToPoint(e.end);return t<0&&i>0||i<0&&t>0}intersectsBox(e){return e.intersectsPlane(this)}intersectsSphere(e){return e.intersectsPlane(this)}coplanarPoint(e){return e.copy(this.normal).multiplyScalar(-this.constant)}applyMatrix4(e,t){let i=t||IA.getNormalMatrix(e),r=this.coplanarPoint(wp).applyMatrix4(e),s=this.normal.applyMatrix3(i).normalize();return this.constant=-r.dot(s),this}translate(e){return this.constant-=e.dot(this.normal),this}equals(e){return e.normal.equals(this.normal)&&e.constant===this.constant}clone(){return new this.constructor().copy(this)}toJSON(){return{normal:this.normal.toArray(),constant:this.constant}}fromJSON(e){return this.normal.fromArray(e.normal),this.constant=e.constant,this}},CA=0,Gr=class extends qi{constructor(){super(),this.isMaterial=!0,Object.defineProperty(this,"id",{value:CA++}),this.uuid=ra(),this.name="",this.type="Material",this.blending=ea,this.side=xs,this.vertexColors=!1,this.opacity=1,this.transparent=!1,this.alphaHash=!1,this.blendSrc=Hp,this.blendDst=Wp,this.blendEquation=zs,this.blendSrcAlpha=null,this.blendDstAlpha=null,this.blendEquationAlpha=null,this.blendColor=new tt(0,0,0),this.blendAlpha=0,this.depthFunc=zo,this.depthTest=!0,this.depthWrite=!0,this.stencilWriteMask=255,this.stencilFunc=Ob,this.stencilRef=0,this.stencilFuncMask=255,this.stencilFail=Eu,this.stencilZFail=Eu,this.stencilZPass=Eu,this.stencilWrite=!1,this.clippingPlanes=null,this.clipIntersection=!1,this.clipShadows=!1,this.shadowSide=null,this.colorWrite=!0,this.precision=null,this.polygonOffset=!1,this.polygonOffsetFactor=0,this.polygonOffsetUnits=0,this.dithering=!1,this.alphaToCoverage=!1,this.premultipliedAlpha=!1,this.forceSinglePass=!1,this.allowOverride=!0,this.visible=!0,this.toneMapped=!0,this.userData={},this.version=0,this._alphaTest=0}get alphaTest(){return this._alphaTest}set alphaTest(e){this._alphaTest>0!=e>0&&this.version++,this._alphaTest=e}onBeforeRender(){}onBeforeCompile(){}customProgramCacheKey(){return this.onBeforeCompile.toString()}setValues(e){if(e!==void 0)for(let t in e){let i=e[t];if(i===void 0){$e(`Material: parameter '${t}' has value of undefined.`);continue}let r=this[t];if(r===void 0){$e(`Material: '${t}' is not a property of THREE.${this.type}.`);continue}r&&r.isColor?r.set(i):r&&r.isVector2&&i&&i.isVector2||r&&r.isEuler&&i&&i.isEuler||r&&r.isVector3&&i&&i.isVector3?r.copy(i):this[t]=i}}toJSON(e){let t=e===void 0||typeof e=="string";t&&(e={textures:{},images:{}});let i={metadata:{version:4.7,type:"Material",generator:"Material.toJSON"}};i.uuid=this.uuid,i.type=this.type,i.blending=this.blending,i.side=this.side,i.shadowSide=this.shadowSide,i.vertexColors=this.vertexColors,i.opacity=this.opacity,i.transparent=this.transparent,i.blendSrc=this.blendSrc,i.blendDst=this.blendDst,i.blendEquation=this.blendEquation,i.blendSrcAlpha=this.blendSrcAlpha,i.blendDstAlpha=this.blendDstAlpha,i.blendEquationAlpha=this.blendEquationAlpha,i.blendColor=this.blendColor.getHex(),i.blendAlpha=this.blendAlpha,i.depthFunc=this.depthFunc,i.depthTest=this.depthTest,i.depthWrite=this.depthWrite,i.colorWrite=this.colorWrite,i.clipIntersection=this.clipIntersection,i.clipShadows=this.clipShadows,i.stencilWriteMask=this.stencilWriteMask,i.stencilFunc=this.stencilFunc,i.stencilRef=this.stencilRef,i.stencilFuncMask=this.stencilFuncMask,i.stencilFail=this.stencilFail,i.stencilZFail=this.stencilZFail,i.stencilZPass=this.stencilZPass,i.stencilWrite=this.stencilWrite,i.polygonOffset=this.polygonOffset,i.polygonOffsetFactor=this.polygonOffsetFactor,i.polygonOffsetUnits=this.polygonOffsetUnits,i.dithering=this.dithering,i.alphaTest=this.alphaTest,i.alphaHash=this.alphaHash,i.alphaToCoverage=this.alphaToCoverage,i.premultipliedAlpha=this.premultipliedAlpha,i.forceSinglePass=this.forceSinglePass,i.allowOverride=this.allowOverride,i.visible=this.visible,i.toneMapped=this.toneMapped,i.name=this.name,this.color&&this.color.isColor&&(i.color=this.color.getHex()),this.roughness!==void 0&&(i.roughness=this.roughness),this.metalness!==void 0&&(i.metalness=this.metalness),this.sheen!==void 0&&(i.sheen=this.sheen),this.sheenColor&&this.sheenColor.isColor&&(i.sheenColor=this.sheenColor.getHex()),this.sheenRoughness!==void 0&&(i.sheenRoughness=this.sheenRoughness),this.emissive&&this.emissive.isColor&&(i.emissive=this.emissive.getHex()),this.emissiveIntensity!==void 0&&(i.emissiveIntensity=this.emissiveIntensity),this.specular&&this.specular.isColor&&(i.specular=this.specular.getHex()),this.specularIntensity!==void 0&&(i.specularIntensity=this.specularIntensity),this.specularColor&&this.specularColor.isColor&&(i.specularColor=this.specularColor.getHex()),this.shininess!==void 0&&(i.shininess=this.shininess),this.clearcoat!==void 0&&(i.clearcoat=this.clearcoat),this.clearcoatRoughness!==void 0&&(i.clearcoatRoughness=this.clearcoatRoughness),this.diffuseRoughness!==void 0&&(i.diffuseRoughness=this.diffuseRoughness),this.diffuseRoughnessMap&&this.diffuseRoughnessMap.isTexture&&(i.diffuseRoughnessMap=this.diffuseRoughnessMap.toJSON(e).uuid),this.clearcoatMap&&this.clearcoatMap.isTexture&&(i.clearcoatMap=this.clearcoatMap.toJSON(e).uuid),this.clearcoatRoughnessMap&&this.clearcoatRoughnessMap.isTexture&&(i.clearcoatRoughnessMap=this.clearcoatRoughnessMap.toJSON(e).uuid),this.clearcoatNormalMap&&this.clearcoatNormalMap.isTexture&&(i.clearcoatNormalMap=this.clearcoatNormalMap.toJSON(e).uuid,i.clearcoatNormalScale=this.clearcoatNormalScale.toArray()),this.sheenColorMap&&this.sheenColorMap.isTexture&&(i.sheenColorMap=this.sheenColorMap.toJSON(e).uuid),this.sheenRoughnessMap&&this.sheenRoughnessMap.isTexture&&(i.sheenRoughnessMap=this.sheenRoughnessMap.toJSON(e).uuid),this.dispersion!==void 0&&(i.dispersion=this.dispersion),this.retroreflectivity!==void 0&&(i.retroreflectivity=this.retroreflectivity),this.iridescence!==void 0&&(i.iridescence=this.iridescence),this.iridescenceIOR!==void 0&&(i.iridescenceIOR=this.iridescenceIOR),this.iridescenceThicknessMinimum!==void 0&&(i.iridescenceThicknessMinimum=this.iridescenceThicknessMinimum),this.iridescenceThicknessMaximum!==void 0&&(i.iridescenceThicknessMaximum=this.iridescenceThicknessMaximum),this.iridescenceMap&&this.iridescenceMap.isTexture&&(i.iridescenceMap=this.iridescenceMap.toJSON(e).uuid),this.iridescenceThicknessMap&&this.iridescenceThicknessMap.isTexture&&(i.iridescenceThicknessMap=this.iridescenceThicknessMap.toJSON(e).uuid),this.anisotropy!==void 0&&(i.anisotropy=this.anisotropy),this.anisotropyRotation!==void 0&&(i.anisotropyRotation=this.anisotropyRotation),this.anisotropyMap&&this.anisotropyMap.isTexture&&(i.anisotropyMap=this.anisotropyMap.toJSON(e).uuid),this.map&&this.map.isTexture&&(i.map=this.map.toJSON(e).uuid),this.matcap&&this.matcap.isTexture&&(i.matcap=this.matcap.toJSON(e).uuid),this.alphaMap&&this.alphaMap.isTexture&&(i.alphaMap=this.alphaMap.toJSON(e).uuid),this.lightMap&&this.lightMap.isTexture&&(i.lightMap=this.lightMap.toJSON(e).uuid,i.lightMapIntensity=this.lightMapIntensity),this.aoMap&&this.aoMap.isTexture&&(i.aoMap=this.aoMap.toJSON(e).uuid,i.aoMapIntensity=this.aoMapIntensity),this.bumpMap&&this.bumpMap.isTexture&&(i.bumpMap=this.bumpMap.toJSON(e).uuid,i.bumpScale=this.bumpScale),this.normalMap&&this.normalMap.isTexture&&(i.normalMap=this.normalMap.toJSON(e).uuid,i.normalMapType=this.normalMapType,i.normalScale=this.normalScale.toArray()),this.displacementMap&&this.displacementMap.isTexture&&(i.displacementMap=this.displacementMap.toJSON(e).uuid,i.displacementScale=this.displacementScale,i.displacementBias=this.displacementBias),this.roughnessMap&&this.roughnessMap.isTexture&&(i.roughnessMap=this.roughnessMap.toJSON(e).uuid),this.metalnessMap&&this.metalnessMap.isTexture&&(i.metalnessMap=this.metalnessMap.toJSON(e).uuid),this.emissiveMap&&this.emissiveMap.isTexture&&(i.emissiveMap=this.emissiveMap.toJSON(e).uuid),this.specularMap&&this.specularMap.isTexture&&(i.specularMap=this.specularMap.toJSON(e).uuid),this.specularIntensityMap&&this.specularIntensityMap.isTexture&&(i.specularIntensityMap=this.specularIntensityMap.toJSON(e).uuid),this.specularColorMap&&this.specularColorMap.isTexture&&(i.specularColorMap=this.specularColorMap.toJSON(e).uuid),this.envMap&&this.envMap.isTexture&&(i.envMap=this.envMap.toJSON(e).uuid,this.combine!==void 0&&(i.combine=this.combine)),this.envMapRotation!==void 0&&(i.envMapRotation=this.envMapRotation.toArray()),this.envMapIntensity!==void 0&&(i.envMapIntensity=this.envMapIntensity),this.reflectivity!==void 0&&(i.reflectivity=this.reflectivity),this.refractionRatio!==void 0&&(i.refractionRatio=this.refractionRatio),this.gradientMap&&this.gradientMap.isTexture&&(i.gradientMap=this.gradientMap.toJSON(e).uuid),this.transmission!==void 0&&(i.transmission=this.transmission),this.transmissionMap&&this.transmissionMap.isTexture&&(i.transmissionMap=this.transmissionMap.toJSON(e).uuid),this.thickness!==void 0&&(i.thickness=this.thickness),this.thicknessMap&&this.thicknessMap.isTexture&&(i.thicknessMap=this.thicknessMap.toJSON(e).uuid),this.attenuationDistance!==void 0&&(i.attenuationDistance=this.attenuationDistance),this.attenuationColor!==void 0&&(i.attenuationColor=this.attenuationColor.getHex()),this.size!==void 0&&(i.size=this.size),this.sizeAttenuation!==void 0&&(i.sizeAttenuation=this.sizeAttenuation),Array.isArray(this.clippingPlanes)&&this.clippingPlanes.length>0&&(i.clippingPlanes=this.clippingPlanes.map(s=>s.toJSON())),this.rotation!==void 0&&(i.rotation=this.rotation),this.depthPacking!==void 0&&(i.depthPacking=this.depthPacking),this.linewidth!==void 0&&(i.linewidth=this.linewidth),this.linecap!==void 0&&(i.linecap=this.linecap),this.linejoin!==void 0&&(i.linejoin=this.linejoin),this.dashSize!==void 0&&(i.dashSize=this.dashSize),this.gapSize!==void 0&&(i.gapSize=this.gapSize),this.scale!==void 0&&(i.scale=this.scale),this.wireframe!==void 0&&(i.wireframe=this.wireframe),this.wireframeLinewidth!==void 0&&(i.wireframeLinewidth=this.wireframeLinewidth),this.wireframeLinecap!==void 0&&(i.wireframeLinecap=this.wireframeLinecap),this.wireframeLinejoin!==void 0&&(i.wireframeLinejoin=this.wireframeLinejoin),this.flatShading!==void 0&&(i.flatShading=this.flatShading),this.fog!==void 0&&(i.fog=this.fog),Object.keys(this.userData).length>0&&(i.userData=this.userData);function r(s){let o=[];for(let a in s){let l=s[a];delete l.metadata,o.push(l)}return o}if(t){let s=r(e.textures),o=r(e.images);s.length>0&&(i.textures=s),o.length>0&&(i.images=o)}return i}fromJSON(e,t){if(e.uuid!==void 0&&(this.uuid=e.uuid),e.name!==void 0&&(this.name=e.name),e.color!==void 0&&this.color!==void 0&&this.color.setHex(e.color),e.roughness!==void 0&&(this.roughness=e.roughness),e.metalness!==void 0&&(this.metalness=e.metalness),e.sheen!==void 0&&(this.sheen=e.sheen),e.sheenColor!==void 0&&(this.sheenColor=new tt().setHex(e.sheenColor)),e.sheenRoughness!==void 0&&(this.sheenRoughness=e.sheenRoughness),e.emissive!==void 0&&this.emissive!==void 0&&this.emissive.setHex(e.emissive),e.specular!==void 0&&this.specular!==void 0&&this.specular.setHex(e.specular),e.specularIntensity!==void 0&&(this.specularIntensity=e.specularIntensity),e.specularColor!==void 0&&this.specularColor!==void 0&&this.specularColor.setHex(e.specularColor),e.shininess!==void 0&&(this.shininess=e.shininess),e.clearcoat!==void 0&&(this.clearcoat=e.clearcoat),e.clearcoatRoughness!==void 0&&(this.clearcoatRoughness=e.clearcoatRoughness),e.diffuseRoughness!==void 0&&(this.diffuseRoughness=e.diffuseRoughness),e.dispersion!==void 0&&(this.dispersion=e.dispersion),e.retroreflectivity!==void 0&&(this.retroreflectivity=e.retroreflectivity),e.iridescence!==void 0&&(this.iridescence=e.iridescence),e.iridescenceIOR!==void 0&&(this.iridescenceIOR=e.iridescenceIOR),e.iridescenceThicknessMinimum!==void 0&&(this.iridescenceThicknessMinimum=e.iridescenceThicknessMinimum),e.iridescenceThicknessMaximum!==void 0&&(this.iridescenceThicknessMaximum=e.iridescenceThicknessMaximum),e.iridescenceThicknessRange!==void 0&&(this.iridescenceThicknessMinimum=e.iridescenceThicknessRange[0],this.iridescenceThicknessMaximum=e.iridescenceThicknessRange[1]),e.transmission!==void 0&&(this.transmission=e.transmission),e.thickness!==void 0&&(this.thickness=e.thickness),e.attenuationDistance!==void 0&&(this.attenuationDistance=e.attenuationDistance),e.attenuationColor!==void 0&&this.attenuationColor!==void 0&&this.attenuationColor.setHex(e.attenuationColor),e.anisotropy!==void 0&&(this.anisotropy=e.anisotropy),e.anisotropyRotation!==void 0&&(this.anisotropyRotation=e.anisotropyRotation),e.fog!==void 0&&(this.fog=e.fog),e.flatShading!==void 0&&(this.flatShading=e.flatShading),e.blending!==void 0&&(this.blending=e.blending),e.combine!==void 0&&(this.combine=e.combine),e.side!==void 0&&(this.side=e.side),e.shadowSide!==void 0&&(this.shadowSide=e.shadowSide),e.opacity!==void 0&&(this.opacity=e.opacity),e.transparent!==void 0&&(this.transparent=e.transparent),e.alphaTest!==void 0&&(this.alphaTest=e.alphaTest),e.alphaHash!==void 0&&(this.alphaHash=e.alphaHash),e.depthFunc!==void 0&&(this.depthFunc=e.depthFunc),e.depthTest!==void 0&&(this.depthTest=e.depthTest),e.depthWrite!==void 0&&(this.depthWrite=e.depthWrite),e.colorWrite!==void 0&&(this.colorWrite=e.colorWrite),e.clippingPlanes!==void 0&&(this.clippingPlanes=e.clippingPlanes.map(i=>new Ei().fromJSON(i))),e.clipIntersection!==void 0&&(this.clipIntersection=e.clipIntersection),e.clipShadows!==void 0&&(this.clipShadows=e.clipShadows),e.depthPacking!==void 0&&(this.depthPacking=e.depthPacking),e.blendSrc!==void 0&&(this.blendSrc=e.blendSrc),e.blendDst!==void 0&&(this.blendDst=e.blendDst),e.blendEquation!==void 0&&(this.blendEquation=e.blendEquation),e.blendSrcAlpha!==void 0&&(this.blendSrcAlpha=e.blendSrcAlpha),e.blendDstAlpha!==void 0&&(this.blendDstAlpha=e.blendDstAlpha),e.blendEquationAlpha!==void 0&&(this.blendEquationAlpha=e.blendEquationAlpha),e.blendColor!==void 0&&this.blendColor!==void 0&&this.blendColor.setHex(e.blendColor),e.blendAlpha!==void 0&&(this.blendAlpha=e.blendAlpha),e.stencilWriteMask!==void 0&&(this.stencilWriteMask=e.stencilWriteMask),e.stencilFunc!==void 0&&(this.stencilFunc=e.stencilFunc),e.stencilRef!==void 0&&(this.stencilRef=e.stencilRef),e.stencilFuncMask!==void 0&&(this.stencilFuncMask=e.stencilFuncMask),e.stencilFail!==void 0&&(this.stencilFail=e.stencilFail),e.stencilZFail!==void 0&&(this.stencilZFail=e.stencilZFail),e.stencilZPass!==void 0&&(this.stencilZPass=e.stencilZPass),e.stencilWrite!==void 0&&(this.stencilWrite=e.stencilWrite),e.wireframe!==void 0&&(this.wireframe=e.wireframe),e.wireframeLinewidth!==void 0&&(this.wireframeLinewidth=e.wireframeLinewidth),e.wireframeLinecap!==void 0&&(this.wireframeLinecap=e.wireframeLinecap),e.wireframeLinejoin!==void 0&&(this.wireframeLinejoin=e.wireframeLinejoin),e.rotation!==void 0&&(this.rotation=e.rotation),e.linewidth!==void 0&&(this.linewidth=e.linewidth),e.linecap!==void 0&&(this.linecap=e.linecap),e.linejoin!==void 0&&(this.linejoin=e.linejoin),e.dashSize!==void 0&&(this.dashSize=e.dashSize),e.gapSize!==void 0&&(this.gapSize=e.gapSize),e.scale!==void 0&&(this.scale=e.scale),e.polygonOffset!==void 0&&(this.polygonOffset=e.polygonOffset),e.polygonOffsetFactor!==void 0&&(this.polygonOffsetFactor=e.polygonOffsetFactor),e.polygonOffsetUnits!==void 0&&(this.polygonOffsetUnits=e.polygonOffsetUnits),e.dithering!==void 0&&(this.dithering=e.dithering),e.alphaToCoverage!==void 0&&(this.alphaToCoverage=e.alphaToCoverage),e.premultipliedAlpha!==void 0&&(this.premultipliedAlpha=e.premultipliedAlpha),e.forceSinglePass!==void 0&&(this.forceSinglePass=e.forceSinglePass),e.allowOverride!==void 0&&(this.allowOverride=e.allowOverride),e.visible!==void 0&&(this.visible=e.visible),e.toneMapped!==void 0&&(this.toneMapped=e.toneMapped),e.userData!==void 0&&(this.userData=e.userData),e.vertexColors!==void 0&&(typeof e.vertexColors=="number"?this.vertexColors=e.vertexColors>0:this.vertexColors=e.vertexColors),e.size!==void 0&&(this.size=e.size),e.sizeAttenuation!==void 0&&(this.sizeAttenuation=e.sizeAttenuation),e.map!==void 0&&(this.map=t[e.map]||null),e.matcap!==void 0&&(this.matcap=t[e.matcap]||null),e.alphaMap!==void 0&&(this.alphaMap=t[e.alphaMap]||null),e.bumpMap!==void 0&&(this.bumpMap=t[e.bumpMap]||null),e.bumpScale!==void 0&&(this.bumpScale=e.bumpScale),e.normalMap!==void 0&&(this.normalMap=t[e.normalMap]||null),e.normalMapType!==void 0&&(this.normalMapType=e.normalMapType),e.normalScale!==void 0){let i=e.normalScale;Array.isArray(i)===!1&&(i=[i,i]),this.normalScale=new Ke().fromArray(i)}return e.displacementMap!==void 0&&(this.displacementMap=t[e.displacementMap]||null),e.displacementScale!==void 0&&(this.displacementScale=e.displacementScale),e.displacementBias!==void 0&&(this.displacementBias=e.displacementBias),e.roughnessMap!==void 0&&(this.roughnessMap=t[e.roughnessMap]||null),e.metalnessMap!==void 0&&(this.metalnessMap=t[e.metalnessMap]||null),e.emissiveMap!==void 0&&(this.emissiveMap=t[e.emissiveMap]||null),e.emissiveIntensity!==void 0&&(this.emissiveIntensity=e.emissiveIntensity),e.specularMap!==void 0&&(this.specularMap=t[e.specularMap]||null),e.specularIntensityMap!==void 0&&(this.specularIntensityMap=t[e.specularIntensityMap]||null),e.specularColorMap!==void 0&&(this.specularColorMap=t[e.specularColorMap]||null),e.envMap!==void 0&&(this.envMap=t[e.envMap]||null),e.envMapRotation!==void 0&&this.envMapRotation.fromArray(e.envMapRotation),e.envMapIntensity!==void 0&&(this.envMapIntensity=e.envMapIntensity),e.reflectivity!==void 0&&(this.reflectivity=e.reflectivity),e.refractionRatio!==void 0&&(this.refractionRatio=e.refractionRatio),e.lightMap!==void 0&&(this.lightMap=t[e.lightMap]||null),e.lightMapIntensity!==void 0&&(this.lightMapIntensity=e.lightMapIntensity),e.aoMap!==void 0&&(this.aoMap=t[e.aoMap]||null),e.aoMapIntensity!==void 0&&(this.aoMapIntensity=e.aoMapIntensity),e.gradientMap!==void 0&&(this.gradientMap=t[e.gradientMap]||null),e.clearcoatMap!==void 0&&(this.clearcoatMap=t[e.clearcoatMap]||null),e.clearcoatRoughnessMap!==void 0&&(this.clearcoatRoughnessMap=t[e.clearcoatRoughnessMap]||null),e.clearcoatNormalMap!==void 0&&(this.clearcoatNormalMap=t[e.clearcoatNormalMap]||null),e.clearcoatNormalScale!==void 0&&(this.clearcoatNormalScale=new Ke().fromArray(e.clearcoatNormalScale)),e.diffuseRoughnessMap!==void 0&&(this.diffuseRoughnessMap=t[e.diffuseRoughnessMap]||null),e.iridescenceMap!==void 0&&(this.iridescenceMap=t[e.iridescenceMap]||null),e.iridescenceThicknessMap!==void 0&&(this.iridescenceThicknessMap=t[e.iridescenceThicknessMap]||null),e.transmissionMap!==void 0&&(this.transmissionMap=t[e.transmissionMap]||null),e.thicknessMap!==void 0&&(this.thicknessMap=t[e.thicknessMap]||null),e.anisotropyMap!==void 0&&(this.anisotropyMap=t[e.anisotropyMap]||null),e.sheenColorMap!==void 0&&(this.sheenColorMap=t[e.sheenColorMap]||null),e.sheenRoughnessMap!==void 0&&(this.sheenRoughnessMap=t[e.sheenRoughnessMap]||null),this}clone(){return new this.constructor().copy(this)}copy(e){this.name=e.name,this.blending=e.blending,this.side=e.side,this.vertexColors=e.vertexColors,this.opacity=e.opacity,this.transparent=e.transparent,this.blendSrc=e.blendSrc,this.blendDst=e.blendDst,this.blendEquation=e.blendEquation,this.blendSrcAlpha=e.blendSrcAlpha,this.blendDstAlpha=e.blendDstAlpha,this.blendEquationAlpha=e.blendEquationAlpha,this.blendColor.copy(e.blendColor),this.blendAlpha=e.blendAlpha,this.depthFunc=e.depthFunc,this.depthTest=e.depthTest,this.depthWrite=e.depthWrite,this.stencilWriteMask=e.stencilWriteMask,this.stencilFunc=e.stencilFunc,this.stencilRef=e.stencilRef,this.stencilFuncMask=e.stencilFuncMask,this.stencilFail=e.stencilFail,this.stencilZFail=e.stencilZFail,this.stencilZPass=e.stencilZPass,this.stencilWrite=e.stencilWrite;let t=e.clippingPlanes,i=null;if(t!==null){let r=t.length;i=new Array(r);for(let s=0;s!==r;++s)i[s]=t[s].clone()}return this.clippingPlanes=i,this.clipIntersection=e.clipIntersection,this.clipShadows=e.clipShadows,this.shadowSide=e.shadowSide,this.colorWrite=e.colorWrite,this.precision=e.precision,this.polygonOffset=e.polygonOffset,this.polygonOffsetFactor=e.polygonOffsetFactor,this.polygonOffsetUnits=e.polygonOffsetUnits,this.dithering=e.dithering,this.alphaTest=e.alphaTest,this.alphaHash=e.alphaHash,this.alphaToCoverage=e.alphaToCoverage,this.premultipliedAlpha=e.premultipliedAlpha,this.forceSinglePass=e.forceSinglePass,this.allowOverride=e.allowOverride,this.visible=e.visible,this.toneMapped=e.toneMapped,this.userData=JSON.parse(JSON.stringify(e.userData)),this}dispose(){this.dispatchEvent({type:"dispose"})}set needsUpdate(e){e===!0&&this.version++}};var Ur=new X,Tp=new X,iu=new X,ru=new X,us=class{constructor(e=new X,t=new X(0,0,-1)){this.origin=e,this.direction=t}set(e,t){return this.origin.copy(e),this.direction.copy(t),this}copy(e){return this.origin.copy(e.origin),this.direction.copy(e.direction),this}at(e,t){return t.copy(this.origin).addScaledVector(this.direction,e)}lookAt(e){return this.direction.copy(e).sub(this.origin).normalize(),this}recast(e){return this.origin.copy(this.at(e,Ur)),this}closestPointToPoint(e,t){t.subVectors(e,this.origin);let i=t.dot(this.direction);return i<0?t.copy(this.origin):t.copy(this.origin).addScaledVector(this.direction,i)}distanceToPoint(e){return Math.sqrt(this.distanceSqToPoint(e))}distanceSqToPoint(e){let t=Ur.subVectors(e,this.origin).dot(this.direction);return t<0?this.origin.distanceToSquared(e):(Ur.copy(this.origin).addScaledVector(this.direction,t),Ur.distanceToSquared(e))}distanceSqToSegment(e,t,i,r){Tp.copy(e).add(t).multiplyScalar(.5),iu.copy(t).sub(e).normalize(),ru.copy(this.origin).sub(Tp);let s=e.distanceTo(t)*.5,o=-this.direction.dot(iu),a=ru.dot(this.direction),l=-ru.dot(iu),c=ru.lengthSq(),u=Math.abs(1-o*o),h,f,d,p;if(u>0)if(h=o*l-a,f=o*a-l,p=s*u,h>=0)if(f>=-p)if(f<=p){let x=1/u;h*=x,f*=x,d=h*(h+o*f+2*a)+f*(o*h+f+2*l)+c}else f=s,h=Math.max(0,-(o*f+a)),d=-h*h+f*(f+2*l)+c;else f=-s,h=Math.max(0,-(o*f+a)),d=-h*h+f*(f+2*l)+c;else f<=-p?(h=Math.max(0,-(-o*s+a)),f=h>0?-s:Math.min(Math.max(-s,-l),s),d=-h*h+f*(f+2*l)+c):f<=p?(h=0,f=Math.min(Math.max(-s,-l),s),d=f*(f+2*l)+c):(h=Math.max(0,-(o*s+a)),f=h>0?s:Math.min(Math.max(-s,-l),s),d=-h*h+f*(f+2*l)+c);else f=o>0?-s:s,h=Math.max(0,-(o*f+a)),d=-h*h+f*(f+2*l)+c;return i&&i.copy(this.origin).addScaledVector(this.direction,h),r&&r.copy(Tp).addScaledVector(iu,f),d}intersectSphere(e,t){if(e.radius<0)return null;Ur.subVectors(e.center,this.origin);let i=Ur.dot(this.direction),r=Ur.dot(Ur)-i*i,s=e.radius*e.radius;if(r>s)return null;let o=Math.sqrt(s-r),a=i-o,l=i+o;return l<0?null:a<0?this.at(l,t):this.at(a,t)}intersectsSphere(e){return e.radius<0?!1:this.distanceSqToPoint(e.center)<=e.radius*e.radius}distanceToPlane(e){let t=e.normal.dot(this.direction);if(t===0)return e.distanceToPoint(this.origin)===0?0:null;let i=-(this.origin.dot(e.normal)+e.constant)/t;return i>=0?i:null}intersectPlane(e,t){let i=this.distanceToPlane(e);return i===null?null:this.at(i,t)}intersectsPlane(e){let t=e.distanceToPoint(this.origin);return t===0||e.normal.dot(this.direction)*t<0}intersectBox(e,t){let i,r,s,o,a,l,c=1/this.direction.x,u=1/this.direction.y,h=1/this.direction.z,f=this.origin;return c>=0?(i=(e.min.x-f.x)*c,r=(e.max.x-f.x)*c):(i=(e.max.x-f.x)*c,r=(e.min.x-f.x)*c),u>=0?(s=(e.min.y-f.y)*u,o=(e.max.y-f.y)*u):(s=(e.max.y-f.y)*u,o=(e.min.y-f.y)*u),i>o||s>r||((s>i||isNaN(i))&&(i=s),(o<r||isNaN(r))&&(r=o),h>=0?(a=(e.min.z-f.z)*h,l=(e.max.z-f.z)*h):(a=(e.max.z-f.z)*h,l=(e.min.z-f.z)*h),i>l||a>r)||((a>i||i!==i)&&(i=a),(l<r||r!==r)&&(r=l),r<0)?null:this.at(i>=0?i:r,t)}intersectsBox(e){return this.intersectBox(e,Ur)!==null}intersectTriangle(e,t,i,r,s){let o=this.origin,a=this.direction,l=a.x,c=a.y,u=a.z,h=e.x-o.x,f=e.y-o.y,d=e.z-o.z,p=t.x-o.x,x=t.y-o.y,m=t.z-o.z,g=i.x-o.x,b=i.y-o.y,T=i.z-o.z,v=Math.abs(l),R=Math.abs(c),A=Math.abs(u),_,E,F,N,P,k,H,D,W,K,z,ce;if(v>=R&&v>=A?(F=l,k=h,W=p,ce=g,l>=0?(_=c,E=u,N=f,P=d,H=x,D=m,K=b,z=T):(_=u,E=c,N=d,P=f,H=m,D=x,K=T,z=b)):R>=A?(F=c,k=f,W=x,ce=b,c>=0?(_=u,E=l,N=d,P=h,H=m,D=p,K=T,z=g):(_=l,E=u,N=h,P=d,H=p,D=m,K=g,z=T)):(F=u,k=d,W=m,ce=T,u>=0?(_=l,E=c,N=h,P=f,H=p,D=x,K=g,z=b):(_=c,E=l,N=f,P=h,H=x,D=p,K=b,z=g)),F===0)return null;let J=_/F,Q=E/F,re=1/F,fe=N-J*k,he=P-Q*k,ee=H-J*W,me=D-Q*W,ye=K-J*ce,Ae=z-Q*ce,Se=ye*me-Ae*ee,Xe=fe*Ae-he*ye,ot=ee*he-me*fe;if(r){if(Se<0||Xe<0||ot<0)return null}else if((Se<0||Xe<0||ot<0)&&(Se>0||Xe>0||ot>0))return null;let ze=Se+Xe+ot;if(ze===0)return null;let ft=re*(Se*k+Xe*W+ot*ce);return(ze>0?ft<0:ft>0)?null:this.at(ft/ze,s)}applyMatrix4(e){return this.origin.applyMatrix4(e),this.direction.transformDirection(e),this}equals(e){return e.origin.equals(this.origin)&&e.direction.equals(this.direction)}clone(){return new this.constructor().copy(this)}},Ou=class extends Gr{constructor(e){super(),this.isMeshBasicMaterial=!0,this.type="MeshBasicMaterial",this.color=new tt(16777215),this.map=null,this.lightMap=null,this.lightMapIntensity=1,this.aoMap=null,this.aoMapIntensity=1,this.specularMap=null,this.alphaMap=null,this.envMap=null,this.envMapRotation=new Ji,this.combine=sh,this.reflectivity=1,this.refractionRatio=.98,this.wireframe=!1,this.wireframeLinewidth=1,this.wireframeLinecap="round",this.wireframeLinejoin="round",this.fog=!0,this.setValues(e)}copy(e){return super.copy(e),this.color.copy(e.color),this.map=e.map,this.lightMap=e.lightMap,this.lightMapIntensity=e.lightMapIntensity,this.aoMap=e.aoMap,this.aoMapIntensity=e.aoMapIntensity,this.specularMap=e.specularMap,this.alphaMap=e.alphaMap,this.envMap=e.envMap,this.envMapRotation.copy(e.envMapRotation),this.combine=e.combine,this.reflectivity=e.reflectivity,this.refractionRatio=e.refractionRatio,this.wireframe=e.wireframe,this.wireframeLinewidth=e.wireframeLinewidth,this.wireframeLinecap=e.wireframeLinecap,this.wireframeLinejoin=e.wireframeLinejoin,this.fog=e.fog,this}},Yx=new Tt,Os=new us,su=new Vr,Zx=new X,ou=new X,au=new X,lu=new X,Ap=new X,cu=new X,Kx=new X,uu=new X,Fi=class extends Xn{constructor(e=new Gn,t=new Ou){super(),this.isMesh=!0,this.type="Mesh",this.geometry=e,this.material=t,this.morphTargetDictionary=void 0,this.morphTargetInfluences=void 0,this.count=1,this.updateMorphTargets()}copy(e,t){return super.copy(e,t),e.morphTargetInfluences!==void 0?this.morphTargetInfluences=e.morphTargetInfluences.slice():this.morphTargetInfluences=void 0,e.morphTargetDictionary!==void 0?this.morphTargetDictionary=Object.assign({},e.morphTargetDictionary):this.morphTargetDictionary=void 0,this.material=Array.isArray(e.material)?e.material.slice():e.material,this.geometry=e.geometry,this}updateMorphTargets(){let t=this.geometry.morphAttributes,i=Object.keys(t);if(i.length>0){let r=t[i[0]];if(r!==void 0){this.morphTargetInfluences=[],this.morphTargetDictionary={};for(let s=0,o=r.length;s<o;s++){let a=r[s].name||String(s);this.morphTargetInfluences.push(0),this.morphTargetDictionary[a]=s}}}}getVertexPosition(e,t){let i=this.geometry,r=i.attributes.position,s=i.morphAttributes.position,o=i.morphTargetsRelative;t.fromBufferAttribute(r,e);let a=this.morphTargetInfluences;if(s&&a){cu.set(0,0,0);for(let l=0,c=s.length;l<c;l++){let u=a[l],h=s[l];u!==0&&(Ap.fromBufferAttribute(h,e),o?cu.addScaledVector(Ap,u):cu.addScaledVector(Ap.sub(t),u))}t.add(cu)}return t}intersectsFrustum(e){return e.intersectsObject(this)}raycast(e,t){let i=this.geometry,r=this.material,s=this.matrixWorld;r!==void 0&&(i.boundingSphere===null&&i.computeBoundingSphere(),su.copy(i.boundingSphere),su.applyMatrix4(s),Os.copy(e.ray).recast(e.near),!(su.containsPoint(Os.origin)===!1&&(Os.intersectSphere(su,Zx)===null||Os.origin.distanceToSquared(Zx)>(e.far-e.near)**2))&&(Yx.copy(s).invert(),Os.copy(e.ray).applyMatrix4(Yx),!(i.boundingBox!==null&&Os.intersectsBox(i.boundingBox)===!1)&&this._computeIntersections(e,t,Os)))}_computeIntersections(e,t,i){let r,s=this.geometry,o=this.material,a=s.index,l=s.attributes.position,c=s.attributes.uv,u=s.attributes.uv1,h=s.attributes.normal,f=s.groups,d=s.drawRange;if(a!==null)if(Array.isArray(o))for(let p=0,x=f.length;p<x;p++){let m=f[p],g=o[m.materialIndex],b=Math.max(m.start,d.start),T=Math.min(a.count,Math.min(m.start+m.count,d.start+d.count));for(let v=b,R=T;v<R;v+=3){let A=a.getX(v),_=a.getX(v+1),E=a.getX(v+2);r=hu(this,g,e,i,c,u,h,A,_,E),r&&(r.faceIndex=Math.floor(v/3),r.face.materialIndex=m.materialIndex,t.push(r))}}else{let p=Math.max(0,d.start),x=Math.min(a.count,d.start+d.count);for(let m=p,g=x;m<g;m+=3){let b=a.getX(m),T=a.getX(m+1),v=a.getX(m+2);r=hu(this,o,e,i,c,u,h,b,T,v),r&&(r.faceIndex=Math.floor(m/3),t.push(r))}}else if(l!==void 0)if(Array.isArray(o))for(let p=0,x=f.length;p<x;p++){let m=f[p],g=o[m.materialIndex],b=Math.max(m.start,d.start),T=Math.min(l.count,Math.min(m.start+m.count,d.start+d.count));for(let v=b,R=T;v<R;v+=3){let A=v,_=v+1,E=v+2;r=hu(this,g,e,i,c,u,h,A,_,E),r&&(r.faceIndex=Math.floor(v/3),r.face.materialIndex=m.materialIndex,t.push(r))}}else{let p=Math.max(0,d.start),x=Math.min(l.count,d.start+d.count);for(let m=p,g=x;m<g;m+=3){let b=m,T=m+1,v=m+2;r=hu(this,o,e,i,c,u,h,b,T,v),r&&(r.faceIndex=Math.floor(m/3),t.push(r))}}}};function NA(n,e,t,i,r,s,o,a){let l;if(e.side===si?l=i.intersectTriangle(o,s,r,!0,a):l=i.intersectTriangle(r,s,o,e.side===xs,a),l===null)return null;uu.copy(a),uu.applyMatrix4(n.matrixWorld);let c=t.ray.origin.distanceTo(uu);return c<t.near||c>t.far?null:{distance:c,point:uu.clone(),object:n}}function hu(n,e,t,i,r,s,o,a,l,c){n.getVertexPosition(a,ou),n.getVertexPosition(l,au),n.getVertexPosition(c,lu);let u=NA(n,e,t,i,ou,au,lu,Kx);if(u){let h=new X;Or.getBarycoord(Kx,ou,au,lu,h),r&&(u.uv=Or.getInterpolatedAttribute(r,a,l,c,h,new Ke)),s&&(u.uv1=Or.getInterpolatedAttribute(s,a,l,c,h,new Ke)),o&&(u.normal=Or.getInterpolatedAttribute(o,a,l,c,h,new X),u.normal.dot(i.direction)>0&&u.normal.multiplyScalar(-1));let f={a,b:l,c,normal:new X,materialIndex:0};Or.getNormal(ou,au,lu,f.normal),u.face=f,u.barycoord=h}return u}var cl=class extends ai{constructor(e=null,t=1,i=1,r,s,o,a,l,c=Vn,u=Vn,h,f){super(null,o,a,l,c,u,r,s,h,f),this.isDataTexture=!0,this.image={data:e,width:t,height:i},this.generateMipmaps=!1,this.flipY=!1,this.unpackAlignment=1}};var hs=class extends kn{constructor(e,t,i,r=1){super(e,t,i),this.isInstancedBufferAttribute=!0,this.meshPerAttribute=r}copy(e){return super.copy(e),this.meshPerAttribute=e.meshPerAttribute,this}toJSON(){let e=super.toJSON();return e.meshPerAttribute=this.meshPerAttribute,e.isInstancedBufferAttribute=!0,e}},Uo=new Tt,$x=new Tt,fu=[],qx=new gr,PA=new Tt,qa=new Fi,Ja=new Vr,ul=class extends Fi{constructor(e,t,i){super(e,t),this.isInstancedMesh=!0,this.instanceMatrix=new hs(new Float32Array(i*16),16),this.instanceColor=null,this.morphTexture=null,this.count=i,this.boundingBox=null,this.boundingSphere=null;for(let r=0;r<i;r++)this.setMatrixAt(r,PA)}computeBoundingBox(){let e=this.geometry,t=this.count;this.boundingBox===null&&(this.boundingBox=new gr),e.boundingBox===null&&e.computeBoundingBox(),this.boundingBox.makeEmpty();for(let i=0;i<t;i++)this.getMatrixAt(i,Uo),qx.copy(e.boundingBox).applyMatrix4(Uo),this.boundingBox.union(qx)}computeBoundingSphere(){let e=this.geometry,t=this.count;this.boundingSphere===null&&(this.boundingSphere=new Vr),e.boundingSphere===null&&e.computeBoundingSphere(),this.boundingSphere.makeEmpty();for(let i=0;i<t;i++)this.getMatrixAt(i,Uo),Ja.copy(e.boundingSphere).applyMatrix4(Uo),this.boundingSphere.union(Ja)}copy(e,t){return super.copy(e,t),this.instanceMatrix.copy(e.instanceMatrix),this.morphTexture=e.morphTexture!==null?e.morphTexture.clone():null,this.instanceColor=e.instanceColor!==null?e.instanceColor.clone():null,this.count=e.count,this.boundingBox=e.boundingBox!==null?e.boundingBox.clone():null,this.boundingSphere=e.boundingSphere!==null?e.boundingSphere.clone():null,this}getColorAt(e,t){return this.instanceColor===null?t.setRGB(1,1,1):t.fromArray(this.instanceColor.array,e*3)}getMatrixAt(e,t){return t.fromArray(this.instanceMatrix.array,e*16)}getMorphAt(e,t){let i=t.morphTargetInfluences,r=this.morphTexture.source.data.data,s=i.length+1,o=e*s+1;for(let a=0;a<i.length;a++)i[a]=r[o+a]}raycast(e,t){let i=this.matrixWorld,r=this.count;if(qa.geometry=this.geometry,qa.material=this.material,qa.material!==void 0&&(this.boundingSphere===null&&this.computeBoundingSphere(),Ja.copy(this.boundingSphere),Ja.applyMatrix4(i),e.ray.intersectsSphere(Ja)!==!1))for(let s=0;s<r;s++){this.getMatrixAt(s,Uo),$x.multiplyMatrices(i,Uo),qa.matrixWorld=$x,qa.raycast(e,fu);for(let o=0,a=fu.length;o<a;o++){let l=fu[o];l.instanceId=s,l.object=this,t.push(l)}fu.length=0}}setColorAt(e,t){return this.instanceColor===null&&(this.instanceColor=new hs(new Float32Array(this.instanceMatrix.count*3).fill(1),3)),t.toArray(this.instanceColor.array,e*3),this}setMatrixAt(e,t){return t.toArray(this.instanceMatrix.array,e*16),this}setMorphAt(e,t){let i=t.morphTargetInfluences,r=i.length+1;this.morphTexture===null&&(this.morphTexture=new cl(new Float32Array(r*this.count),r,this.count,fh,Ui));let s=this.morphTexture.source.data.data,o=0;for(let c=0;c<i.length;c++)o+=i[c];let a=this.geometry.morphTargetsRelative?1:1-o,l=r*e;return s[l]=a,s.set(i,l+1),this}updateMorphTargets(){}dispose(){super.dispose(),this.instanceMatrix.dispose(),this.instanceColor!==null&&this.instanceColor.dispose(),this.morphTexture!==null&&(this.morphTexture.dispose(),this.morphTexture=null)}},Bs=new Vr,LA=new Ke(.5,.5),du=new X,fs=class{constructor(e=new Ei,t=new Ei,i=new Ei,r=new Ei,s=new Ei,o=new Ei){this.planes=[e,t,i,r,s,o]}set(e,t,i,r,s,o){let a=this.planes;return a[0].copy(e),a[1].copy(t),a[2].copy(i),a[3].copy(r),a[4].copy(s),a[5].copy(o),this}copy(e){let t=this.planes;for(let i=0;i<6;i++)t[i].copy(e.planes[i]);return this}setFromProjectionMatrix(e,t=Di,i=!1){let r=this.planes,s=e.elements,o=s[0],a=s[1],l=s[2],c=s[3],u=s[4],h=s[5],f=s[6],d=s[7],p=s[8],x=s[9],m=s[10],g=s[11],b=s[12],T=s[13],v=s[14],R=s[15];if(r[0].setComponents(c-o,d-u,g-p,R-b).normalize(),r[1].setComponents(c+o,d+u,g+p,R+b).normalize(),r[2].setComponents(c+a,d+h,g+x,R+T).normalize(),r[3].setComponents(c-a,d-h,g-x,R-T).normalize(),i)r[4].setComponents(l,f,m,v).normalize(),r[5].setComponents(c-l,d-f,g-m,R-v).normalize();else if(r[4].setComponents(c-l,d-f,g-m,R-v).normalize(),t===Di)r[5].setComponents(c+l,d+f,g+m,R+v).normalize();else if(t===Ho)r[5].setComponents(l,f,m,v).normalize();else throw new Error("THREE.Frustum.setFromProjectionMatrix(): Invalid coordinate system: "+t);return this}intersectsObject(e){if(e.boundingSphere!==void 0)e.boundingSphere===null&&e.computeBoundingSphere(),Bs.copy(e.boundingSphere).applyMatrix4(e.matrixWorld);else{let t=e.geometry;t.boundingSphere===null&&t.computeBoundingSphere(),Bs.copy(t.boundingSphere).applyMatrix4(e.matrixWorld)}return this.intersectsSphere(Bs)}intersectsSprite(e){Bs.center.set(0,0,0);let t=LA.distanceTo(e.center);return Bs.radius=.7071067811865476+t,Bs.applyMatrix4(e.matrixWorld),this.intersectsSphere(Bs)}intersectsSphere(e){let t=this.planes,i=e.center,r=-e.radius;for(let s=0;s<6;s++)if(t[s].distanceToPoint(i)<r)return!1;return!0}intersectsBox(e){let t=this.planes;for(let i=0;i<6;i++){let r=t[i];if(du.x=r.normal.x>0?e.max.x:e.min.x,du.y=r.normal.y>0?e.max.y:e.min.y,du.z=r.normal.z>0?e.max.z:e.min.z,r.distanceToPoint(du)<0)return!1}return!0}containsPoint(e){let t=this.planes;for(let i=0;i<6;i++)if(t[i].distanceToPoint(e)<0)return!1;return!0}clone(){return new this.constructor().copy(this)}},Jx=new Tt,Bu=class n{constructor(){this.coordinateSystem=Di,this._frustums=[],this._count=0}setFromArrayCamera(e){let t=e.cameras,i=this._frustums;for(let r=0;r<t.length;r++){let s=t[r];Jx.multiplyMatrices(s.projectionMatrix,s.matrixWorldInverse),i[r]===void 0&&(i[r]=new fs),i[r].setFromProjectionMatrix(Jx,s.coordinateSystem,s.reversedDepth)}return this._count=t.length,this}getFrustum(e){return this._frustums[e]}intersectsObject(e){let t=this._frustums;for(let i=0;i<this._count;i++)if(t[i].intersectsObject(e))return!0;return!1}intersectsSprite(e){let t=this._frustums;for(let i=0;i<this._count;i++)if(t[i].intersectsSprite(e))return!0;return!1}intersectsSphere(e){let t=this._frustums;for(let i=0;i<this._count;i++)if(t[i].intersectsSphere(e))return!0;return!1}intersectsBox(e){let t=this._frustums;for(let i=0;i<this._count;i++)if(t[i].intersectsBox(e))return!0;return!1}containsPoint(e){let t=this._frustums;for(let i=0;i<this._count;i++)if(t[i].containsPoint(e))return!0;return!1}copy(e){this.coordinateSystem=e.coordinateSystem;let t=this._frustums,i=e._frustums;for(let r=0;r<e._count;r++)t[r]===void 0&&(t[r]=new fs),t[r].copy(i[r]);return this._count=e._count,this}clone(){return new n().copy(this)}};var Vs=class extends Gr{constructor(e){super(),this.isLineBasicMaterial=!0,this.type="LineBasicMaterial",this.color=new tt(16777215),this.map=null,this.linewidth=1,this.linecap="round",this.linejoin="round",this.fog=!0,this.setValues(e)}copy(e){return super.copy(e),this.color.copy(e.color),this.map=e.map,this.linewidth=e.linewidth,this.linecap=e.linecap,this.linejoin=e.linejoin,this.fog=e.fog,this}},ku=new X,Vu=new X,jx=new Tt,ja=new us,pu=new Vr,Rp=new X,Qx=new X,Gu=class extends Xn{constructor(e=new Gn,t=new Vs){super(),this.isLine=!0,this.type="Line",this.geometry=e,this.material=t,this.morphTargetDictionary=void 0,this.morphTargetInfluences=void 0,this.updateMorphTargets()}copy(e,t){return super.copy(e,t),e.morphTargetInfluences!==void 0?this.morphTargetInfluences=e.morphTargetInfluences.slice():this.morphTargetInfluences=void 0,e.morphTargetDictionary!==void 0?this.morphTargetDictionary=Object.assign({},e.morphTargetDictionary):this.morphTargetDictionary=void 0,this.material=Array.isArray(e.material)?e.material.slice():e.material,this.geometry=e.geometry,this}computeLineDistances(){let e=this.geometry;if(e.index===null){let t=e.attributes.position,i=[0];for(let r=1,s=t.count;r<s;r++)ku.fromBufferAttribute(t,r-1),Vu.fromBufferAttribute(t,r),i[r]=i[r-1],i[r]+=ku.distanceTo(Vu);e.setAttribute("lineDistance",new jt(i,1))}else $e("Line.computeLineDistances(): Computation only possible with non-indexed BufferGeometry.");return this}intersectsFrustum(e){return e.intersectsObject(this)}raycast(e,t){let i=this.geometry,r=this.matrixWorld,s=e.params.Line.threshold,o=i.drawRange;if(i.boundingSphere===null&&i.computeBoundingSphere(),pu.copy(i.boundingSphere),pu.applyMatrix4(r),pu.radius+=s,e.ray.intersectsSphere(pu)===!1)return;jx.copy(r).invert(),ja.copy(e.ray).applyMatrix4(jx);let a=s/((this.scale.x+this.scale.y+this.scale.z)/3),l=a*a,c=this.isLineSegments?2:1,u=i.index,f=i.attributes.position;if(u!==null){let d=Math.max(0,o.start),p=Math.min(u.count,o.start+o.count);for(let x=d,m=p-1;x<m;x+=c){let g=u.getX(x),b=u.getX(x+1),T=mu(this,e,ja,l,g,b,x);T&&t.push(T)}if(this.isLineLoop){let x=u.getX(p-1),m=u.getX(d),g=mu(this,e,ja,l,x,m,p-1);g&&t.push(g)}}else{let d=Math.max(0,o.start),p=Math.min(f.count,o.start+o.count);for(let x=d,m=p-1;x<m;x+=c){let g=mu(this,e,ja,l,x,x+1,x);g&&t.push(g)}if(this.isLineLoop){let x=mu(this,e,ja,l,p-1,d,p-1);x&&t.push(x)}}}updateMorphTargets(){let t=this.geometry.morphAttributes,i=Object.keys(t);if(i.length>0){let r=t[i[0]];if(r!==void 0){this.morphTargetInfluences=[],this.morphTargetDictionary={};for(let s=0,o=r.length;s<o;s++){let a=r[s].name||String(s);this.morphTargetInfluences.push(0),this.morphTargetDictionary[a]=s}}}}};function mu(n,e,t,i,r,s,o){let a=n.geometry.attributes.position;if(ku.fromBufferAttribute(a,r),Vu.fromBufferAttribute(a,s),t.distanceSqToSegment(ku,Vu,Rp,Qx)>i)return;Rp.applyMatrix4(n.matrixWorld);let c=e.ray.origin.distanceTo(Rp);if(!(c<e.near||c>e.far))return{distance:c,point:Qx.clone().applyMatrix4(n.matrixWorld),index:o,face:null,faceIndex:null,barycoord:null,object:n}}var eb=new X,tb=new X,$o=class extends Gu{constructor(e,t){super(e,t),this.isLineSegments=!0,this.type="LineSegments"}computeLineDistances(){let e=this.geometry;if(e.index===null){let t=e.attributes.position,i=[];for(let r=0,s=t.count;r<s;r+=2)eb.fromBufferAttribute(t,r),tb.fromBufferAttribute(t,r+1),i[r]=r===0?0:i[r-1],i[r+1]=i[r]+eb.distanceTo(tb);e.setAttribute("lineDistance",new jt(i,1))}else $e("LineSegments.computeLineDistances(): Computation only possible with non-indexed BufferGeometry.");return this}};var hl=class extends ai{constructor(e=[],t=Hs,i,r,s,o,a,l,c,u){super(e,t,i,r,s,o,a,l,c,u),this.isCubeTexture=!0,this.flipY=!1}get images(){return this.image}set images(e){this.image=e}};var zr=class extends ai{constructor(e,t,i=ji,r,s,o,a=Vn,l=Vn,c,u=kr,h=1){if(u!==kr&&u!==Wr)throw new Error("THREE.DepthTexture: format must be either THREE.DepthFormat or THREE.DepthStencilFormat");let f={width:e,height:t,depth:h};super(f,r,s,o,a,l,u,i,c),this.isDepthTexture=!0,this.flipY=!1,this.generateMipmaps=!1,this.compareFunction=null}copy(e){return super.copy(e),this.source=new Yo(Object.assign({},e.image)),this.compareFunction=e.compareFunction,this}toJSON(e){let t=super.toJSON(e);return t.compareFunction=this.compareFunction,t}},fl=class extends zr{constructor(e,t=ji,i=Hs,r,s,o=Vn,a=Vn,l,c=kr){let u={width:e,height:e,depth:1},h=[u,u,u,u,u,u];super(e,e,t,i,r,s,o,a,l,c),this.image=h,this.isCubeDepthTexture=!0,this.isCubeTexture=!0}get images(){return this.image}set images(e){this.image=e}},dl=class extends ai{constructor(e=null){super(),this.sourceTexture=e,this.isExternalTexture=!0}copy(e){return super.copy(e),this.sourceTexture=e.sourceTexture,this}},ds=class n extends Gn{constructor(e=1,t=1,i=1,r=1,s=1,o=1){super(),this.type="BoxGeometry",this.parameters={width:e,height:t,depth:i,widthSegments:r,heightSegments:s,depthSegments:o};let a=this;r=Math.floor(r),s=Math.floor(s),o=Math.floor(o);let l=[],c=[],u=[],h=[],f=0,d=0;p("z","y","x",-1,-1,i,t,e,o,s,0),p("z","y","x",1,-1,i,t,-e,o,s,1),p("x","z","y",1,1,e,i,t,r,o,2),p("x","z","y",1,-1,e,i,-t,r,o,3),p("x","y","z",1,-1,e,t,i,r,s,4),p("x","y","z",-1,-1,e,t,-i,r,s,5),this.setIndex(l),this.setAttribute("position",new jt(c,3)),this.setAttribute("normal",new jt(u,3)),this.setAttribute("uv",new jt(h,2));function p(x,m,g,b,T,v,R,A,_,E,F){let N=v/_,P=R/E,k=v/2,H=R/2,D=A/2,W=_+1,K=E+1,z=0,ce=0,J=new X;for(let Q=0;Q<K;Q++){let re=Q*P-H;for(let fe=0;fe<W;fe++){let he=fe*N-k;J[x]=he*b,J[m]=re*T,J[g]=D,c.push(J.x,J.y,J.z),J[x]=0,J[m]=0,J[g]=A>0?1:-1,u.push(J.x,J.y,J.z),h.push(fe/_),h.push(1-Q/E),z+=1}}for(let Q=0;Q<E;Q++)for(let re=0;re<_;re++){let fe=f+re+W*Q,he=f+re+W*(Q+1),ee=f+(re+1)+W*(Q+1),me=f+(re+1)+W*Q;l.push(fe,he,me),l.push(he,ee,me),ce+=6}a.addGroup(d,ce,F),d+=ce,f+=z}}copy(e){return super.copy(e),this.parameters=Object.assign({},e.parameters),this}static fromJSON(e){return new n(e.width,e.height,e.depth,e.widthSegments,e.heightSegments,e.depthSegments)}};var zu=class n extends Gn{constructor(e=1,t=1,i=1,r=32,s=1,o=!1,a=0,l=Math.PI*2){super(),this.type="CylinderGeometry",this.parameters={radiusTop:e,radiusBottom:t,height:i,radialSegments:r,heightSegments:s,openEnded:o,thetaStart:a,thetaLength:l};let c=this;r=Math.floor(r),s=Math.floor(s);let u=[],h=[],f=[],d=[],p=0,x=[],m=i/2,g=0;b(),o===!1&&(e>0&&T(!0),t>0&&T(!1)),this.setIndex(u),this.setAttribute("position",new jt(h,3)),this.setAttribute("normal",new jt(f,3)),this.setAttribute("uv",new jt(d,2));function b(){let v=new X,R=new X,A=0,_=(t-e)/i;for(let E=0;E<=s;E++){let F=[],N=E/s,P=N*(t-e)+e;for(let k=0;k<=r;k++){let H=k/r,D=H*l+a,W=Math.sin(D),K=Math.cos(D);R.x=P*W,R.y=-N*i+m,R.z=P*K,h.push(R.x,R.y,R.z),v.set(W,_,K).normalize(),f.push(v.x,v.y,v.z),d.push(H,1-N),F.push(p++)}x.push(F)}for(let E=0;E<r;E++)for(let F=0;F<s;F++){let N=x[F][E],P=x[F+1][E],k=x[F+1][E+1],H=x[F][E+1];(e>0||F!==0)&&(u.push(N,P,H),A+=3),(t>0||F!==s-1)&&(u.push(P,k,H),A+=3)}c.addGroup(g,A,0),g+=A}function T(v){let R=p,A=new Ke,_=new X,E=0,F=v===!0?e:t,N=v===!0?1:-1;for(let k=1;k<=r;k++)h.push(0,m*N,0),f.push(0,N,0),d.push(.5,.5),p++;let P=p;for(let k=0;k<=r;k++){let D=k/r*l+a,W=Math.cos(D),K=Math.sin(D);_.x=F*K,_.y=m*N,_.z=F*W,h.push(_.x,_.y,_.z),f.push(0,N,0),A.x=W*.5+.5,A.y=K*.5*N+.5,d.push(A.x,A.y),p++}for(let k=0;k<r;k++){let H=R+k,D=P+k;v===!0?u.push(D,D+1,H):u.push(D+1,D,H),E+=3}c.addGroup(g,E,v===!0?1:2),g+=E}}copy(e){return super.copy(e),this.parameters=Object.assign({},e.parameters),this}static fromJSON(e){return new n(e.radiusTop,e.radiusBottom,e.height,e.radialSegments,e.heightSegments,e.openEnded,e.thetaStart,e.thetaLength)}},pl=class n extends zu{constructor(e=1,t=1,i=32,r=1,s=!1,o=0,a=Math.PI*2){super(0,e,t,i,r,s,o,a),this.type="ConeGeometry",this.parameters={radius:e,height:t,radialSegments:i,heightSegments:r,openEnded:s,thetaStart:o,thetaLength:a}}static fromJSON(e){return new n(e.radius,e.height,e.radialSegments,e.heightSegments,e.openEnded,e.thetaStart,e.thetaLength)}},Hu=class n extends Gn{constructor(e=[],t=[],i=1,r=0){super(),this.type="PolyhedronGeometry",this.parameters={vertices:e,indices:t,radius:i,detail:r};let s=[],o=[];a(r),c(i),u(),this.setAttribute("position",new jt(s,3)),this.setAttribute("normal",new jt(s.slice(),3)),this.setAttribute("uv",new jt(o,2)),r===0?this.computeVertexNormals():this.normalizeNormals();function a(b){let T=new X,v=new X,R=new X;for(let A=0;A<t.length;A+=3)d(t[A+0],T),d(t[A+1],v),d(t[A+2],R),l(T,v,R,b)}function l(b,T,v,R){let A=R+1,_=[];for(let E=0;E<=A;E++){_[E]=[];let F=b.clone().lerp(v,E/A),N=T.clone().lerp(v,E/A),P=A-E;for(let k=0;k<=P;k++)k===0&&E===A?_[E][k]=F:_[E][k]=F.clone().lerp(N,k/P)}for(let E=0;E<A;E++)for(let F=0;F<2*(A-E)-1;F++){let N=Math.floor(F/2);F%2===0?(f(_[E][N+1]),f(_[E+1][N]),f(_[E][N])):(f(_[E][N+1]),f(_[E+1][N+1]),f(_[E+1][N]))}}function c(b){let T=new X;for(let v=0;v<s.length;v+=3)T.x=s[v+0],T.y=s[v+1],T.z=s[v+2],T.normalize().multiplyScalar(b),s[v+0]=T.x,s[v+1]=T.y,s[v+2]=T.z}function u(){let b=new X;for(let T=0;T<s.length;T+=3){b.x=s[T+0],b.y=s[T+1],b.z=s[T+2];let v=m(b)/2/Math.PI+.5,R=g(b)/Math.PI+.5;o.push(v,1-R)}p(),h()}function h(){for(let b=0;b<o.length;b+=6){let T=o[b+0],v=o[b+2],R=o[b+4],A=Math.max(T,v,R),_=Math.min(T,v,R);A>.9&&_<.1&&(T<.2&&(o[b+0]+=1),v<.2&&(o[b+2]+=1),R<.2&&(o[b+4]+=1))}}function f(b){s.push(b.x,b.y,b.z)}function d(b,T){let v=b*3;T.x=e[v+0],T.y=e[v+1],T.z=e[v+2]}function p(){let b=new X,T=new X,v=new X,R=new X,A=new Ke,_=new Ke,E=new Ke;for(let F=0,N=0;F<s.length;F+=9,N+=6){b.set(s[F+0],s[F+1],s[F+2]),T.set(s[F+3],s[F+4],s[F+5]),v.set(s[F+6],s[F+7],s[F+8]),A.set(o[N+0],o[N+1]),_.set(o[N+2],o[N+3]),E.set(o[N+4],o[N+5]),R.copy(b).add(T).add(v).divideScalar(3);let P=m(R);x(A,N+0,b,P),x(_,N+2,T,P),x(E,N+4,v,P)}}function x(b,T,v,R){R<0&&b.x===1&&(o[T]=b.x-1),v.x===0&&v.z===0&&(o[T]=R/2/Math.PI+.5)}function m(b){return Math.atan2(b.z,-b.x)}function g(b){return Math.atan2(-b.y,Math.sqrt(b.x*b.x+b.z*b.z))}}copy(e){return super.copy(e),this.parameters=Object.assign({},e.parameters),this}static fromJSON(e){return new n(e.vertices,e.indices,e.radius,e.detail)}};var gu=new X,_u=new X,Ip=new X,yu=new Or,ml=class extends Gn{constructor(e=null,t=1){if(super(),this.type="EdgesGeometry",this.parameters={geometry:e,thresholdAngle:t},e!==null){let r=Math.pow(10,4),s=Math.cos(Vo*t),o=e.getIndex(),a=e.getAttribute("position"),l=o?o.count:a.count,c=[0,0,0],u=["a","b","c"],h=new Array(3),f=new Map,d=[];for(let p=0;p<l;p+=3){o?(c[0]=o.getX(p),c[1]=o.getX(p+1),c[2]=o.getX(p+2)):(c[0]=p,c[1]=p+1,c[2]=p+2);let{a:x,b:m,c:g}=yu;if(x.fromBufferAttribute(a,c[0]),m.fromBufferAttribute(a,c[1]),g.fromBufferAttribute(a,c[2]),yu.getNormal(Ip),h[0]=`${Math.round(x.x*r)},${Math.round(x.y*r)},${Math.round(x.z*r)}`,h[1]=`${Math.round(m.x*r)},${Math.round(m.y*r)},${Math.round(m.z*r)}`,h[2]=`${Math.round(g.x*r)},${Math.round(g.y*r)},${Math.round(g.z*r)}`,!(h[0]===h[1]||h[1]===h[2]||h[2]===h[0]))for(let b=0;b<3;b++){let T=(b+1)%3,v=h[b],R=h[T],A=yu[u[b]],_=yu[u[T]],E=`${v}_${R}`,F=`${R}_${v}`,N=f.get(F);N?(Ip.dot(N.normal)<=s&&(d.push(A.x,A.y,A.z),d.push(_.x,_.y,_.z)),f.set(F,null)):f.has(E)||f.set(E,{index0:c[b],index1:c[T],normal:Ip.clone()})}}for(let p of f.values())if(p){let{index0:x,index1:m}=p;gu.fromBufferAttribute(a,x),_u.fromBufferAttribute(a,m),d.push(gu.x,gu.y,gu.z),d.push(_u.x,_u.y,_u.z)}this.setAttribute("position",new jt(d,3))}}copy(e){return super.copy(e),this.parameters=Object.assign({},e.parameters),this}};var qo=class n extends Hu{constructor(e=1,t=0){let i=(1+Math.sqrt(5))/2,r=[-1,i,0,1,i,0,-1,-i,0,1,-i,0,0,-1,i,0,1,i,0,-1,-i,0,1,-i,i,0,-1,i,0,1,-i,0,-1,-i,0,1],s=[0,11,5,0,5,1,0,1,7,0,7,10,0,10,11,1,5,9,5,11,4,11,10,2,10,7,6,7,1,8,3,9,4,3,4,2,3,2,6,3,6,8,3,8,9,4,9,5,2,4,11,6,2,10,8,6,7,9,8,1];super(r,s,e,t),this.type="IcosahedronGeometry",this.parameters={radius:e,detail:t}}static fromJSON(e){return new n(e.radius,e.detail)}};var gl=class n extends Gn{constructor(e=1,t=1,i=1,r=1){super(),this.type="PlaneGeometry",this.parameters={width:e,height:t,widthSegments:i,heightSegments:r};let s=e/2,o=t/2,a=Math.floor(i),l=Math.floor(r),c=a+1,u=l+1,h=e/a,f=t/l,d=[],p=[],x=[],m=[];for(let g=0;g<u;g++){let b=g*f-o;for(let T=0;T<c;T++){let v=T*h-s;p.push(v,-b,0),x.push(0,0,1),m.push(T/a),m.push(1-g/l)}}for(let g=0;g<l;g++)for(let b=0;b<a;b++){let T=b+c*g,v=b+c*(g+1),R=b+1+c*(g+1),A=b+1+c*g;d.push(T,v,A),d.push(v,R,A)}this.setIndex(d),this.setAttribute("position",new jt(p,3)),this.setAttribute("normal",new jt(x,3)),this.setAttribute("uv",new jt(m,2))}copy(e){return super.copy(e),this.parameters=Object.assign({},e.parameters),this}static fromJSON(e){return new n(e.width,e.height,e.widthSegments,e.heightSegments)}};function Xs(n){let e={};for(let t in n){e[t]={};for(let i in n[t]){let r=n[t][i];if(nb(r))r.isRenderTargetTexture?($e("UniformsUtils: Textures of render targets cannot be cloned via cloneUniforms() or mergeUniforms()."),e[t][i]=null):e[t][i]=r.clone();else if(Array.isArray(r))if(nb(r[0])){let s=[];for(let o=0,a=r.length;o<a;o++)s[o]=r[o].clone();e[t][i]=s}else e[t][i]=r.slice();else e[t][i]=r}}return e}function qn(n){let e={};for(let t=0;t<n.length;t++){let i=Xs(n[t]);for(let r in i)e[r]=i[r]}return e}function nb(n){return n&&(n.isColor||n.isMatrix3||n.isMatrix4||n.isVector2||n.isVector3||n.isVector4||n.isTexture||n.isQuaternion)}function DA(n){let e=[];for(let t=0;t<n.length;t++)e.push(n[t].clone());return e}function dm(n){let e=n.getRenderTarget();return e===null?n.outputColorSpace:e.isXRRenderTarget===!0?e.texture.colorSpace:St.workingColorSpace}var Jb={clone:Xs,merge:qn},FA=`void main() {
	gl_Position = projectionMatrix * modelViewMatrix * vec4( position, 1.0 );
}`,UA=`void main() {
	gl_FragColor = vec4( 1.0, 0.0, 0.0, 1.0 );
}`,_r=class extends Gr{constructor(e){super(),this.isShaderMaterial=!0,this.type="ShaderMaterial",this.defines={},this.uniforms={},this.uniformsGroups=[],this.vertexShader=FA,this.fragmentShader=UA,this.linewidth=1,this.wireframe=!1,this.wireframeLinewidth=1,this.fog=!1,this.lights=!1,this.clipping=!1,this.forceSinglePass=!0,this.extensions={clipCullDistance:!1,multiDraw:!1},this.defaultAttributeValues={color:[1,1,1],uv:[0,0],uv1:[0,0]},this.index0AttributeName=void 0,this.uniformsNeedUpdate=!1,this.glslVersion=null,e!==void 0&&this.setValues(e)}copy(e){return super.copy(e),this.fragmentShader=e.fragmentShader,this.vertexShader=e.vertexShader,this.uniforms=Xs(e.uniforms),this.uniformsGroups=DA(e.uniformsGroups),this.defines=Object.assign({},e.defines),this.wireframe=e.wireframe,this.wireframeLinewidth=e.wireframeLinewidth,this.fog=e.fog,this.lights=e.lights,this.clipping=e.clipping,this.extensions=Object.assign({},e.extensions),this.glslVersion=e.glslVersion,this.defaultAttributeValues=Object.assign({},e.defaultAttributeValues),this.index0AttributeName=e.index0AttributeName,this.uniformsNeedUpdate=e.uniformsNeedUpdate,this}toJSON(e){let t=super.toJSON(e);t.glslVersion=this.glslVersion,t.uniforms={};for(let r in this.uniforms){let o=this.uniforms[r].value;o&&o.isTexture?t.uniforms[r]={type:"t",value:o.toJSON(e).uuid}:o&&o.isColor?t.uniforms[r]={type:"c",value:o.getHex()}:o&&o.isVector2?t.uniforms[r]={type:"v2",value:o.toArray()}:o&&o.isVector3?t.uniforms[r]={type:"v3",value:o.toArray()}:o&&o.isVector4?t.uniforms[r]={type:"v4",value:o.toArray()}:o&&o.isMatrix3?t.uniforms[r]={type:"m3",value:o.toArray()}:o&&o.isMatrix4?t.uniforms[r]={type:"m4",value:o.toArray()}:t.uniforms[r]={value:o}}Object.keys(this.defines).length>0&&(t.defines=this.defines),t.vertexShader=this.vertexShader,t.fragmentShader=this.fragmentShader,t.lights=this.lights,t.clipping=this.clipping;let i={};for(let r in this.extensions)this.extensions[r]===!0&&(i[r]=!0);return Object.keys(i).length>0&&(t.extensions=i),t}fromJSON(e,t){if(super.fromJSON(e,t),e.uniforms!==void 0)for(let i in e.uniforms){let r=e.uniforms[i];switch(this.uniforms[i]={},r.type){case"t":this.uniforms[i].value=t[r.value]||null;break;case"c":this.uniforms[i].value=new tt().setHex(r.value);break;case"v2":this.uniforms[i].value=new Ke().fromArray(r.value);break;case"v3":this.uniforms[i].value=new X().fromArray(r.value);break;case"v4":this.uniforms[i].value=new tn().fromArray(r.value);break;case"m3":this.uniforms[i].value=new it().fromArray(r.value);break;case"m4":this.uniforms[i].value=new Tt().fromArray(r.value);break;default:this.uniforms[i].value=r.value}}if(e.defines!==void 0&&(this.defines=e.defines),e.vertexShader!==void 0&&(this.vertexShader=e.vertexShader),e.fragmentShader!==void 0&&(this.fragmentShader=e.fragmentShader),e.glslVersion!==void 0&&(this.glslVersion=e.glslVersion),e.extensions!==void 0)for(let i in e.extensions)this.extensions[i]=e.extensions[i];return e.lights!==void 0&&(this.lights=e.lights),e.clipping!==void 0&&(this.clipping=e.clipping),this}},Wu=class extends _r{constructor(e){super(e),this.isRawShaderMaterial=!0,this.type="RawShaderMaterial"}};var _l=class extends Gr{constructor(e){super(),this.isMeshLambertMaterial=!0,this.type="MeshLambertMaterial",this.color=new tt(16777215),this.map=null,this.lightMap=null,this.lightMapIntensity=1,this.aoMap=null,this.aoMapIntensity=1,this.emissive=new tt(0),this.emissiveIntensity=1,this.emissiveMap=null,this.bumpMap=null,this.bumpScale=1,this.normalMap=null,this.normalMapType=Yh,this.normalScale=new Ke(1,1),this.displacementMap=null,this.displacementScale=1,this.displacementBias=0,this.specularMap=null,this.alphaMap=null,this.envMap=null,this.envMapRotation=new Ji,this.combine=sh,this.reflectivity=1,this.envMapIntensity=1,this.refractionRatio=.98,this.wireframe=!1,this.wireframeLinewidth=1,this.wireframeLinecap="round",this.wireframeLinejoin="round",this.flatShading=!1,this.fog=!0,this.setValues(e)}copy(e){return super.copy(e),this.color.copy(e.color),this.map=e.map,this.lightMap=e.lightMap,this.lightMapIntensity=e.lightMapIntensity,this.aoMap=e.aoMap,this.aoMapIntensity=e.aoMapIntensity,this.emissive.copy(e.emissive),this.emissiveMap=e.emissiveMap,this.emissiveIntensity=e.emissiveIntensity,this.bumpMap=e.bumpMap,this.bumpScale=e.bumpScale,this.normalMap=e.normalMap,this.normalMapType=e.normalMapType,this.normalScale.copy(e.normalScale),this.displacementMap=e.displacementMap,this.displacementScale=e.displacementScale,this.displacementBias=e.displacementBias,this.specularMap=e.specularMap,this.alphaMap=e.alphaMap,this.envMap=e.envMap,this.envMapRotation.copy(e.envMapRotation),this.combine=e.combine,this.reflectivity=e.reflectivity,this.envMapIntensity=e.envMapIntensity,this.refractionRatio=e.refractionRatio,this.wireframe=e.wireframe,this.wireframeLinewidth=e.wireframeLinewidth,this.wireframeLinecap=e.wireframeLinecap,this.wireframeLinejoin=e.wireframeLinejoin,this.flatShading=e.flatShading,this.fog=e.fog,this}},Xu=class extends Gr{constructor(e){super(),this.isMeshDepthMaterial=!0,this.type="MeshDepthMaterial",this.depthPacking=Fb,this.map=null,this.alphaMap=null,this.displacementMap=null,this.displacementScale=1,this.displacementBias=0,this.wireframe=!1,this.wireframeLinewidth=1,this.setValues(e)}copy(e){return super.copy(e),this.depthPacking=e.depthPacking,this.map=e.map,this.alphaMap=e.alphaMap,this.displacementMap=e.displacementMap,this.displacementScale=e.displacementScale,this.displacementBias=e.displacementBias,this.wireframe=e.wireframe,this.wireframeLinewidth=e.wireframeLinewidth,this}},Yu=class extends Gr{constructor(e){super(),this.isMeshDistanceMaterial=!0,this.type="MeshDistanceMaterial",this.map=null,this.alphaMap=null,this.displacementMap=null,this.displacementScale=1,this.displacementBias=0,this.setValues(e)}copy(e){return super.copy(e),this.map=e.map,this.alphaMap=e.alphaMap,this.displacementMap=e.displacementMap,this.displacementScale=e.displacementScale,this.displacementBias=e.displacementBias,this}};function Oo(n,e){return!n||n.constructor===e?n:typeof e.BYTES_PER_ELEMENT=="number"?new e(n):Array.prototype.slice.call(n)}function xu(n){return n!==void 0&&n.inTangents!==void 0&&n.outTangents!==void 0}var ps=class{constructor(e,t,i,r){this.parameterPositions=e,this._cachedIndex=0,this.resultBuffer=r!==void 0?r:new t.constructor(i),this.sampleValues=t,this.valueSize=i,this.settings=null,this.DefaultSettings_={}}evaluate(e){let t=this.parameterPositions,i=this._cachedIndex,r=t[i],s=t[i-1];n:{e:{let o;t:{i:if(!(e<r)){for(let a=i+2;;){if(r===void 0){if(e<s)break i;return i=t.length,this._cachedIndex=i,this.copySampleValue_(i-1)}if(i===a)break;if(s=r,r=t[++i],e<r)break e}o=t.length;break t}if(!(e>=s)){let a=t[1];e<a&&(i=2,s=a);for(let l=i-2;;){if(s===void 0)return this._cachedIndex=0,this.copySampleValue_(0);if(i===l)break;if(r=s,s=t[--i-1],e>=s)break e}o=i,i=0;break t}break n}for(;i<o;){let a=i+o>>>1;e<t[a]?o=a:i=a+1}if(r=t[i],s=t[i-1],s===void 0)return this._cachedIndex=0,this.copySampleValue_(0);if(r===void 0)return i=t.length,this._cachedIndex=i,this.copySampleValue_(i-1)}this._cachedIndex=i,this.intervalChanged_(i,s,r)}return this.interpolate_(i,s,e,r)}getSettings_(){return this.settings||this.DefaultSettings_}copySampleValue_(e){let t=this.resultBuffer,i=this.sampleValues,r=this.valueSize,s=e*r;for(let o=0;o!==r;++o)t[o]=i[s+o];return t}interpolate_(){throw new Error("THREE.Interpolant: Call to abstract method.")}intervalChanged_(){}},Zu=class extends ps{constructor(e,t,i,r){super(e,t,i,r),this._weightPrev=-0,this._offsetPrev=-0,this._weightNext=-0,this._offsetNext=-0,this.DefaultSettings_={endingStart:Pp,endingEnd:Pp}}intervalChanged_(e,t,i){let r=this.parameterPositions,s=e-2,o=e+1,a=r[s],l=r[o];if(a===void 0)switch(this.getSettings_().endingStart){case Lp:s=e,a=2*t-i;break;case Dp:s=r.length-2,a=t+r[s]-r[s+1];break;default:s=e,a=i}if(l===void 0)switch(this.getSettings_().endingEnd){case Lp:o=e,l=2*i-t;break;case Dp:o=1,l=i+r[1]-r[0];break;default:o=e-1,l=t}let c=(i-t)*.5,u=this.valueSize;this._weightPrev=c/(t-a),this._weightNext=c/(l-i),this._offsetPrev=s*u,this._offsetNext=o*u}interpolate_(e,t,i,r){let s=this.resultBuffer,o=this.sampleValues,a=this.valueSize,l=e*a,c=l-a,u=this._offsetPrev,h=this._offsetNext,f=this._weightPrev,d=this._weightNext,p=(i-t)/(r-t),x=p*p,m=x*p,g=-f*m+2*f*x-f*p,b=(1+f)*m+(-1.5-2*f)*x+(-.5+f)*p+1,T=(-1-d)*m+(1.5+d)*x+.5*p,v=d*m-d*x;for(let R=0;R!==a;++R)s[R]=g*o[u+R]+b*o[c+R]+T*o[l+R]+v*o[h+R];return s}},Ku=class extends ps{constructor(e,t,i,r){super(e,t,i,r)}interpolate_(e,t,i,r){let s=this.resultBuffer,o=this.sampleValues,a=this.valueSize,l=e*a,c=l-a,u=(i-t)/(r-t),h=1-u;for(let f=0;f!==a;++f)s[f]=o[c+f]*h+o[l+f]*u;return s}},$u=class extends ps{constructor(e,t,i,r){super(e,t,i,r)}interpolate_(e){return this.copySampleValue_(e-1)}},qu=class extends ps{interpolate_(e,t,i,r){let s=this.resultBuffer,o=this.sampleValues,a=this.valueSize,l=e*a,c=l-a,u=this.inTangents,h=this.outTangents;if(!u||!h){let p=(i-t)/(r-t),x=1-p;for(let m=0;m!==a;++m)s[m]=o[c+m]*x+o[l+m]*p;return s}let f=a*2,d=e-1;for(let p=0;p!==a;++p){let x=o[c+p],m=o[l+p],g=d*f+p*2,b=h[g],T=h[g+1],v=e*f+p*2,R=u[v],A=u[v+1],_=BA(i,t,b,R,r);s[p]=jb(_,x,T,A,m)}return s}};function jb(n,e,t,i,r){let s=1-n;return s*s*s*e+3*s*s*n*t+3*s*n*n*i+n*n*n*r}function OA(n,e,t,i,r){let s=1-n;return 3*s*s*(t-e)+6*s*n*(i-t)+3*n*n*(r-i)}function BA(n,e,t,i,r){let s=(n-e)/(r-e);for(let o=0;o<8;o++){let a=jb(s,e,t,i,r)-n;if(Math.abs(a)<1e-10)break;let l=OA(s,e,t,i,r);if(Math.abs(l)<1e-10)break;s=Math.max(0,Math.min(1,s-a/l))}return s}var Ti=class{constructor(e,t,i,r){if(e===void 0)throw new Error("THREE.KeyframeTrack: track name is undefined");if(t===void 0||t.length===0)throw new Error("THREE.KeyframeTrack: no keyframes in track named "+e);this.name=e,this.times=Oo(t,this.TimeBufferType),this.values=Oo(i,this.ValueBufferType),this.setInterpolation(r||this.DefaultInterpolation)}static toJSON(e){let t=e.constructor,i;if(t.toJSON!==this.toJSON)i=t.toJSON(e);else{i={name:e.name,times:Oo(e.times,Array),values:Oo(e.values,Array)};let r=e.getInterpolation();r!==e.DefaultInterpolation&&(i.interpolation=r),xu(e.settings)&&(i.settings={inTangents:Oo(e.settings.inTangents,Array),outTangents:Oo(e.settings.outTangents,Array)})}return i.type=e.ValueTypeName,i}InterpolantFactoryMethodDiscrete(e){return new $u(this.times,this.values,this.getValueSize(),e)}InterpolantFactoryMethodLinear(e){return new Ku(this.times,this.values,this.getValueSize(),e)}InterpolantFactoryMethodSmooth(e){return new Zu(this.times,this.values,this.getValueSize(),e)}InterpolantFactoryMethodBezier(e){let t=new qu(this.times,this.values,this.getValueSize(),e);return this.settings&&(t.inTangents=this.settings.inTangents,t.outTangents=this.settings.outTangents),t}setInterpolation(e){let t;switch(e){case tl:t=this.InterpolantFactoryMethodDiscrete;break;case Lu:t=this.InterpolantFactoryMethodLinear;break;case Su:t=this.InterpolantFactoryMethodSmooth;break;case Np:t=this.InterpolantFactoryMethodBezier;break}if(t===void 0){let i="unsupported interpolation for "+this.ValueTypeName+" keyframe track named "+this.name;if(this.createInterpolant===void 0)if(e!==this.DefaultInterpolation)this.setInterpolation(this.DefaultInterpolation);else throw new Error(i);return $e("KeyframeTrack:",i),this}return this.createInterpolant=t,this}getInterpolation(){switch(this.createInterpolant){case this.InterpolantFactoryMethodDiscrete:return tl;case this.InterpolantFactoryMethodLinear:return Lu;case this.InterpolantFactoryMethodSmooth:return Su;case this.InterpolantFactoryMethodBezier:return Np}}getValueSize(){return this.values.length/this.times.length}shift(e){if(e!==0){let t=this.times;for(let i=0,r=t.length;i!==r;++i)t[i]+=e;xu(this.settings)&&(ib(this.settings.inTangents,e),ib(this.settings.outTangents,e))}return this}scale(e){if(e!==1){let t=this.times;for(let i=0,r=t.length;i!==r;++i)t[i]*=e;xu(this.settings)&&(rb(this.settings.inTangents,e),rb(this.settings.outTangents,e))}return this}trim(e,t){let i=this.times,r=i.length,s=0,o=r-1;for(;s!==r&&i[s]<e;)++s;for(;o!==-1&&i[o]>t;)--o;if(++o,s!==0||o!==r){s>=o&&(o=Math.max(o,1),s=o-1);let a=this.getValueSize();this.times=i.slice(s,o),this.values=this.values.slice(s*a,o*a)}return this}validate(){let e=!0,t=this.getValueSize();t-Math.floor(t)!==0&&(et("KeyframeTrack: Invalid value size in track.",this),e=!1);let i=this.times,r=this.values,s=i.length;s===0&&(et("KeyframeTrack: Track is empty.",this),e=!1);let o=null;for(let a=0;a!==s;a++){let l=i[a];if(typeof l=="number"&&isNaN(l)){et("KeyframeTrack: Time is not a valid number.",this,a,l),e=!1;break}if(o!==null&&o>l){et("KeyframeTrack: Out of order keys.",this,a,l,o),e=!1;break}o=l}if(r!==void 0&&QT(r))for(let a=0,l=r.length;a!==l;++a){let c=r[a];if(isNaN(c)){et("KeyframeTrack: Value is not a valid number.",this,a,c),e=!1;break}}return e}optimize(){let e=this.times.slice(),t=this.values.slice(),i=this.getValueSize(),r=this.getInterpolation()===Su,s=e.length-1,o=1;for(let a=1;a<s;++a){let l=!1,c=e[a],u=e[a+1];if(c!==u&&(a!==1||c!==e[0]))if(r)l=!0;else{let h=a*i,f=h-i,d=h+i;for(let p=0;p!==i;++p){let x=t[h+p];if(x!==t[f+p]||x!==t[d+p]){l=!0;break}}}if(l){if(a!==o){e[o]=e[a];let h=a*i,f=o*i;for(let d=0;d!==i;++d)t[f+d]=t[h+d]}++o}}if(s>0){e[o]=e[s];for(let a=s*i,l=o*i,c=0;c!==i;++c)t[l+c]=t[a+c];++o}return o!==e.length?(this.times=e.slice(0,o),this.values=t.slice(0,o*i)):(this.times=e,this.values=t),this}clone(){let e=this.times.slice(),t=this.values.slice(),i=this.constructor,r=new i(this.name,e,t);return r.createInterpolant=this.createInterpolant,xu(this.settings)&&(r.settings={inTangents:this.settings.inTangents.slice(),outTangents:this.settings.outTangents.slice()}),r}};function ib(n,e){for(let t=0,i=n.length;t!==i;t+=2)n[t]+=e}function rb(n,e){for(let t=0,i=n.length;t!==i;t+=2)n[t]*=e}Ti.prototype.ValueTypeName="";Ti.prototype.TimeBufferType=Float32Array;Ti.prototype.ValueBufferType=Float32Array;Ti.prototype.DefaultInterpolation=Lu;var ms=class extends Ti{constructor(e,t,i){super(e,t,i)}};ms.prototype.ValueTypeName="bool";ms.prototype.ValueBufferType=Array;ms.prototype.DefaultInterpolation=tl;ms.prototype.InterpolantFactoryMethodLinear=void 0;ms.prototype.InterpolantFactoryMethodSmooth=void 0;var Ju=class extends Ti{constructor(e,t,i,r){super(e,t,i,r)}};Ju.prototype.ValueTypeName="color";var ju=class extends Ti{constructor(e,t,i,r){super(e,t,i,r)}};ju.prototype.ValueTypeName="number";var Qu=class extends ps{constructor(e,t,i,r){super(e,t,i,r)}interpolate_(e,t,i,r){let s=this.resultBuffer,o=this.sampleValues,a=this.valueSize,l=(i-t)/(r-t),c=e*a;for(let u=c+a;c!==u;c+=4)Mi.slerpFlat(s,0,o,c-a,o,c,l);return s}},yl=class extends Ti{constructor(e,t,i,r){super(e,t,i,r)}InterpolantFactoryMethodLinear(e){return new Qu(this.times,this.values,this.getValueSize(),e)}};yl.prototype.ValueTypeName="quaternion";yl.prototype.InterpolantFactoryMethodSmooth=void 0;var gs=class extends Ti{constructor(e,t,i){super(e,t,i)}};gs.prototype.ValueTypeName="string";gs.prototype.ValueBufferType=Array;gs.prototype.DefaultInterpolation=tl;gs.prototype.InterpolantFactoryMethodLinear=void 0;gs.prototype.InterpolantFactoryMethodSmooth=void 0;var eh=class extends Ti{constructor(e,t,i,r){super(e,t,i,r)}};eh.prototype.ValueTypeName="vector";var th=class{constructor(e,t,i){let r=this,s=!1,o=0,a=0,l,c=[];this.onStart=void 0,this.onLoad=e,this.onProgress=t,this.onError=i,this._abortController=null,this.itemStart=function(u){a++,s===!1&&r.onStart!==void 0&&r.onStart(u,o,a),s=!0},this.itemEnd=function(u){o++,r.onProgress!==void 0&&r.onProgress(u,o,a),o===a&&(s=!1,r.onLoad!==void 0&&r.onLoad())},this.itemError=function(u){r.onError!==void 0&&r.onError(u)},this.resolveURL=function(u){return u=u.normalize("NFC"),l?l(u):u},this.setURLModifier=function(u){return l=u,this},this.addHandler=function(u,h){return c.push(u,h),this},this.removeHandler=function(u){let h=c.indexOf(u);return h!==-1&&c.splice(h,2),this},this.getHandler=function(u){for(let h=0,f=c.length;h<f;h+=2){let d=c[h],p=c[h+1];if(d.global&&(d.lastIndex=0),d.test(u))return p}return null},this.abort=function(){return this.abortController.abort(),this._abortController=null,this}}get abortController(){return this._abortController||(this._abortController=new AbortController),this._abortController}},Qb=new th,nh=class{constructor(e){this.manager=e!==void 0?e:Qb,this.crossOrigin="anonymous",this.withCredentials=!1,this.path="",this.resourcePath="",this.requestHeader={},this.priority="auto",this.cache="default",typeof __THREE_DEVTOOLS__<"u"&&__THREE_DEVTOOLS__.dispatchEvent(new CustomEvent("observe",{detail:this}))}load(){}loadAsync(e,t){let i=this;return new Promise(function(r,s){i.load(e,r,t,s)})}parse(){}setCrossOrigin(e){return this.crossOrigin=e,this}setWithCredentials(e){return this.withCredentials=e,this}setPath(e){return this.path=e,this}setResourcePath(e){return this.resourcePath=e,this}setRequestHeader(e){return this.requestHeader=e,this}setPriority(e){return this.priority=e,this}setCache(e){return this.cache=e,this}abort(){return this}};nh.DEFAULT_MATERIAL_NAME="__DEFAULT";var xl=class extends Xn{static registerNode(e){this.prototype._lightNode=e}constructor(e,t=1){super(),this.isLight=!0,this.type="Light",this.color=new tt(e),this.intensity=t}copy(e,t){return super.copy(e,t),this.color.copy(e.color),this.intensity=e.intensity,this}toJSON(e){let t=super.toJSON(e);return t.object.color=this.color.getHex(),t.object.intensity=this.intensity,t}},bl=class extends xl{constructor(e,t,i){super(e,i),this.isHemisphereLight=!0,this.type="HemisphereLight",this.position.copy(Xn.DEFAULT_UP),this.updateMatrix(),this.groundColor=new tt(t)}copy(e,t){return super.copy(e,t),this.groundColor.copy(e.groundColor),this}toJSON(e){let t=super.toJSON(e);return t.object.groundColor=this.groundColor.getHex(),t}},Cp=new Tt,sb=new X,ob=new X,ih=class{constructor(e){this.camera=e,this.intensity=1,this.bias=0,this.biasNode=null,this.normalBias=0,this.radius=1,this.blurSamples=8,this.mapSize=new Ke(512,512),this.mapType=li,this.map=null,this.mapPass=null,this.matrix=new Tt,this.autoUpdate=!0,this.needsUpdate=!1,this._frustum=new fs,this._frameExtents=new Ke(1,1),this._viewportCount=1,this._viewports=[new tn(0,0,1,1)]}getViewportCount(){return this._viewportCount}getCamera(){return this.camera}getFrustum(){return this._frustum}updateMatrices(e){let t=this.camera;sb.setFromMatrixPosition(e.matrixWorld),t.position.copy(sb),ob.setFromMatrixPosition(e.target.matrixWorld),t.lookAt(ob),t.updateMatrixWorld(),this._updateMatrix(t,this.matrix,this._frustum)}_updateMatrix(e,t,i,r){Cp.multiplyMatrices(e.projectionMatrix,e.matrixWorldInverse),i.setFromProjectionMatrix(Cp,e.coordinateSystem,e.reversedDepth);let s=this._frameExtents,o=r?r.z/s.x:1,a=r?r.w/s.y:1,l=r?r.x/s.x:0,c=r?r.y/s.y:0;e.coordinateSystem===Ho||e.reversedDepth?t.set(.5*o,0,0,.5*o+l,0,.5*a,0,.5*a+c,0,0,1,0,0,0,0,1):t.set(.5*o,0,0,.5*o+l,0,.5*a,0,.5*a+c,0,0,.5,.5,0,0,0,1),t.multiply(Cp)}getViewport(e){return this._viewports[e]}getFrameExtents(){return this._frameExtents}dispose(){this.map&&this.map.dispose(),this.mapPass&&this.mapPass.dispose()}copy(e){return this.camera=e.camera.clone(),this.intensity=e.intensity,this.bias=e.bias,this.radius=e.radius,this.autoUpdate=e.autoUpdate,this.needsUpdate=e.needsUpdate,this.normalBias=e.normalBias,this.blurSamples=e.blurSamples,this.mapSize.copy(e.mapSize),this.mapType=e.mapType,this.biasNode=e.biasNode,this}clone(){return new this.constructor().copy(this)}toJSON(){let e={};return e.intensity=this.intensity,e.bias=this.bias,e.normalBias=this.normalBias,e.radius=this.radius,e.blurSamples=this.blurSamples,e.mapSize=this.mapSize.toArray(),e.mapType=this.mapType,e.camera=this.camera.toJSON(!1).object,delete e.camera.matrix,e}},bu=new X,vu=new Mi,pr=new X,vl=class extends Xn{constructor(){super(),this.isCamera=!0,this.type="Camera",this.matrixWorldInverse=new Tt,this.projectionMatrix=new Tt,this.projectionMatrixInverse=new Tt,this.coordinateSystem=Di,this._reversedDepth=!1}get reversedDepth(){return this._reversedDepth}copy(e,t){return super.copy(e,t),this.matrixWorldInverse.copy(e.matrixWorldInverse),this.projectionMatrix.copy(e.projectionMatrix),this.projectionMatrixInverse.copy(e.projectionMatrixInverse),this.coordinateSystem=e.coordinateSystem,this}getWorldDirection(e){return super.getWorldDirection(e).negate()}updateMatrixWorld(e){super.updateMatrixWorld(e),this.matrixWorld.decompose(bu,vu,pr),pr.x===1&&pr.y===1&&pr.z===1?this.matrixWorldInverse.copy(this.matrixWorld).invert():this.matrixWorldInverse.compose(bu,vu,pr.set(1,1,1)).invert()}updateWorldMatrix(e,t,i=!1){super.updateWorldMatrix(e,t,i),this.matrixWorld.decompose(bu,vu,pr),pr.x===1&&pr.y===1&&pr.z===1?this.matrixWorldInverse.copy(this.matrixWorld).invert():this.matrixWorldInverse.compose(bu,vu,pr.set(1,1,1)).invert()}clone(){return new this.constructor().copy(this)}},cs=new X,ab=new Ke,lb=new Ke,ii=class extends vl{constructor(e=50,t=1,i=.1,r=2e3){super(),this.isPerspectiveCamera=!0,this.type="PerspectiveCamera",this.fov=e,this.zoom=1,this.near=i,this.far=r,this.focus=10,this.aspect=t,this.view=null,this.filmGauge=35,this.filmOffset=0,this.updateProjectionMatrix()}copy(e,t){return super.copy(e,t),this.fov=e.fov,this.zoom=e.zoom,this.near=e.near,this.far=e.far,this.focus=e.focus,this.aspect=e.aspect,this.view=e.view===null?null:Object.assign({},e.view),this.filmGauge=e.filmGauge,this.filmOffset=e.filmOffset,this}setFocalLength(e){let t=.5*this.getFilmHeight()/e;this.fov=Xo*2*Math.atan(t),this.updateProjectionMatrix()}getFocalLength(){let e=Math.tan(Vo*.5*this.fov);return .5*this.getFilmHeight()/e}getEffectiveFOV(){return Xo*2*Math.atan(Math.tan(Vo*.5*this.fov)/this.zoom)}getFilmWidth(){return this.filmGauge*Math.min(this.aspect,1)}getFilmHeight(){return this.filmGauge/Math.max(this.aspect,1)}getViewBounds(e,t,i){cs.set(-1,-1,.5).applyMatrix4(this.projectionMatrixInverse),t.set(cs.x,cs.y).multiplyScalar(-e/cs.z),cs.set(1,1,.5).applyMatrix4(this.projectionMatrixInverse),i.set(cs.x,cs.y).multiplyScalar(-e/cs.z)}getViewSize(e,t){return this.getViewBounds(e,ab,lb),t.subVectors(lb,ab)}setViewOffset(e,t,i,r,s,o){this.aspect=e/t,this.view===null&&(this.view={enabled:!0,fullWidth:1,fullHeight:1,offsetX:0,offsetY:0,width:1,height:1}),this.view.enabled=!0,this.view.fullWidth=e,this.view.fullHeight=t,this.view.offsetX=i,this.view.offsetY=r,this.view.width=s,this.view.height=o,this.updateProjectionMatrix()}clearViewOffset(){this.view!==null&&(this.view.enabled=!1),this.updateProjectionMatrix()}updateProjectionMatrix(){let e=this.near,t=e*Math.tan(Vo*.5*this.fov)/this.zoom,i=2*t,r=this.aspect*i,s=-.5*r,o=this.view;if(this.view!==null&&this.view.enabled){let l=o.fullWidth,c=o.fullHeight;s+=o.offsetX*r/l,t-=o.offsetY*i/c,r*=o.width/l,i*=o.height/c}let a=this.filmOffset;a!==0&&(s+=e*a/this.getFilmWidth()),this.projectionMatrix.makePerspective(s,s+r,t,t-i,e,this.far,this.coordinateSystem,this.reversedDepth),this.projectionMatrixInverse.copy(this.projectionMatrix).invert()}toJSON(e){let t=super.toJSON(e);return t.object.fov=this.fov,t.object.zoom=this.zoom,t.object.near=this.near,t.object.far=this.far,t.object.focus=this.focus,t.object.aspect=this.aspect,this.view!==null&&(t.object.view=Object.assign({},this.view)),t.object.filmGauge=this.filmGauge,t.object.filmOffset=this.filmOffset,t}};var Sl=class extends vl{constructor(e=-1,t=1,i=1,r=-1,s=.1,o=2e3){super(),this.isOrthographicCamera=!0,this.type="OrthographicCamera",this.zoom=1,this.view=null,this.left=e,this.right=t,this.top=i,this.bottom=r,this.near=s,this.far=o,this.updateProjectionMatrix()}copy(e,t){return super.copy(e,t),this.left=e.left,this.right=e.right,this.top=e.top,this.bottom=e.bottom,this.near=e.near,this.far=e.far,this.zoom=e.zoom,this.view=e.view===null?null:Object.assign({},e.view),this}setViewOffset(e,t,i,r,s,o){this.view===null&&(this.view={enabled:!0,fullWidth:1,fullHeight:1,offsetX:0,offsetY:0,width:1,height:1}),this.view.enabled=!0,this.view.fullWidth=e,this.view.fullHeight=t,this.view.offsetX=i,this.view.offsetY=r,this.view.width=s,this.view.height=o,this.updateProjectionMatrix()}clearViewOffset(){this.view!==null&&(this.view.enabled=!1),this.updateProjectionMatrix()}updateProjectionMatrix(){let e=(this.right-this.left)/(2*this.zoom),t=(this.top-this.bottom)/(2*this.zoom),i=(this.right+this.left)/2,r=(this.top+this.bottom)/2,s=i-e,o=i+e,a=r+t,l=r-t;if(this.view!==null&&this.view.enabled){let c=(this.right-this.left)/this.view.fullWidth/this.zoom,u=(this.top-this.bottom)/this.view.fullHeight/this.zoom;s+=c*this.view.offsetX,o=s+c*this.view.width,a-=u*this.view.offsetY,l=a-u*this.view.height}this.projectionMatrix.makeOrthographic(s,o,a,l,this.near,this.far,this.coordinateSystem,this.reversedDepth),this.projectionMatrixInverse.copy(this.projectionMatrix).invert()}toJSON(e){let t=super.toJSON(e);return t.object.zoom=this.zoom,t.object.left=this.left,t.object.right=this.right,t.object.top=this.top,t.object.bottom=this.bottom,t.object.near=this.near,t.object.far=this.far,this.view!==null&&(t.object.view=Object.assign({},this.view)),t}},Fp=class extends ih{constructor(){super(new Sl(-5,5,5,-5,.5,500)),this.isDirectionalLightShadow=!0}},El=class extends xl{constructor(e,t){super(e,t),this.isDirectionalLight=!0,this.type="DirectionalLight",this.position.copy(Xn.DEFAULT_UP),this.updateMatrix(),this.target=new Xn,this.shadow=new Fp}dispose(){super.dispose(),this.shadow.dispose()}copy(e){return super.copy(e),this.target=e.target.clone(),this.shadow=e.shadow.clone(),this}toJSON(e){let t=super.toJSON(e);return t.object.shadow=this.shadow.toJSON(),t.object.target=this.target.uuid,t}};var Bo=-90,ko=1,Jo=class extends Xn{constructor(e,t,i){super(),this.type="CubeCamera",this.renderTarget=i,this.coordinateSystem=null,this.activeMipmapLevel=0;let r=new ii(Bo,ko,e,t);r.layers=this.layers,this.add(r);let s=new ii(Bo,ko,e,t);s.layers=this.layers,this.add(s);let o=new ii(Bo,ko,e,t);o.layers=this.layers,this.add(o);let a=new ii(Bo,ko,e,t);a.layers=this.layers,this.add(a);let l=new ii(Bo,ko,e,t);l.layers=this.layers,this.add(l);let c=new ii(Bo,ko,e,t);c.layers=this.layers,this.add(c)}updateCoordinateSystem(){let e=this.coordinateSystem,t=this.children.concat(),[i,r,s,o,a,l]=t;for(let c of t)this.remove(c);if(e===Di)i.up.set(0,1,0),i.lookAt(1,0,0),r.up.set(0,1,0),r.lookAt(-1,0,0),s.up.set(0,0,-1),s.lookAt(0,1,0),o.up.set(0,0,1),o.lookAt(0,-1,0),a.up.set(0,1,0),a.lookAt(0,0,1),l.up.set(0,1,0),l.lookAt(0,0,-1);else if(e===Ho)i.up.set(0,-1,0),i.lookAt(-1,0,0),r.up.set(0,-1,0),r.lookAt(1,0,0),s.up.set(0,0,1),s.lookAt(0,1,0),o.up.set(0,0,-1),o.lookAt(0,-1,0),a.up.set(0,-1,0),a.lookAt(0,0,1),l.up.set(0,-1,0),l.lookAt(0,0,-1);else throw new Error("THREE.CubeCamera.updateCoordinateSystem(): Invalid coordinate system: "+e);for(let c of t)this.add(c),c.updateMatrixWorld()}update(e,t){this.parent===null&&this.updateMatrixWorld();let{renderTarget:i,activeMipmapLevel:r}=this;this.coordinateSystem!==e.coordinateSystem&&(this.coordinateSystem=e.coordinateSystem,this.updateCoordinateSystem());let[s,o,a,l,c,u]=this.children,h=e.getRenderTarget(),f=e.getActiveCubeFace(),d=e.getActiveMipmapLevel(),p=e.xr.enabled;e.xr.enabled=!1;let x=i.texture.mipmapsAutoUpdate;i.texture.mipmapsAutoUpdate=!1;let m=!1;e.isWebGLRenderer===!0?m=e.state.buffers.depth.getReversed():m=e.reversedDepthBuffer,e.setRenderTarget(i,0,r),m&&e.autoClear===!1&&e.clearDepth(),e.render(t,s),e.setRenderTarget(i,1,r),m&&e.autoClear===!1&&e.clearDepth(),e.render(t,o),e.setRenderTarget(i,2,r),m&&e.autoClear===!1&&e.clearDepth(),e.render(t,a),e.setRenderTarget(i,3,r),m&&e.autoClear===!1&&e.clearDepth(),e.render(t,l),e.setRenderTarget(i,4,r),m&&e.autoClear===!1&&e.clearDepth(),e.render(t,c),i.texture.mipmapsAutoUpdate=x,e.setRenderTarget(i,5,r),m&&e.autoClear===!1&&e.clearDepth(),e.render(t,u),e.setRenderTarget(h,f,d),e.xr.enabled=p,i.texture.needsPMREMUpdate=!0}},rh=class extends ii{constructor(e=[]){super(),this.isArrayCamera=!0,this.isMultiViewCamera=!1,this.cameras=e,this.perCameraFrustumCulled=!1}};var pm="\\[\\]\\.:\\/",kA=new RegExp("["+pm+"]","g"),mm="[^"+pm+"]",VA="[^"+pm.replace("\\.","")+"]",GA=/((?:WC+[\/:])*)/.source.replace("WC",mm),zA=/(WCOD+)?/.source.replace("WCOD",VA),HA=/(?:\.(WC+)(?:\[(.+)\])?)?/.source.replace("WC",mm),WA=/\.(WC+)(?:\[(.+)\])?/.source.replace("WC",mm),XA=new RegExp("^"+GA+zA+HA+WA+"$"),YA=["material","materials","bones","map"],Up=class{constructor(e,t,i){let r=i||Jt.parseTrackName(t);this._targetGroup=e,this._bindings=e.subscribe_(t,r)}getValue(e,t){this.bind();let i=this._targetGroup.nCachedObjects_,r=this._bindings[i];r!==void 0&&r.getValue(e,t)}setValue(e,t){let i=this._bindings;for(let r=this._targetGroup.nCachedObjects_,s=i.length;r!==s;++r)i[r].setValue(e,t)}bind(){let e=this._bindings;for(let t=this._targetGroup.nCachedObjects_,i=e.length;t!==i;++t)e[t].bind()}unbind(){let e=this._bindings;for(let t=this._targetGroup.nCachedObjects_,i=e.length;t!==i;++t)e[t].unbind()}},Jt=class n{constructor(e,t,i){this.path=t,this.parsedPath=i||n.parseTrackName(t),this.node=n.findNode(e,this.parsedPath.nodeName),this.rootNode=e,this.getValue=this._getValue_unbound,this.setValue=this._setValue_unbound}static create(e,t,i){return e&&e.isAnimationObjectGroup?new n.Composite(e,t,i):new n(e,t,i)}static sanitizeNodeName(e){return e.replace(/\s/g,"_").replace(kA,"")}static parseTrackName(e){let t=XA.exec(e);if(t===null)throw new Error("THREE.PropertyBinding: Cannot parse trackName: "+e);let i={nodeName:t[2],objectName:t[3],objectIndex:t[4],propertyName:t[5],propertyIndex:t[6]},r=i.nodeName&&i.nodeName.lastIndexOf(".");if(r!==void 0&&r!==-1){let s=i.nodeName.substring(r+1);YA.indexOf(s)!==-1&&(i.nodeName=i.nodeName.substring(0,r),i.objectName=s)}if(i.propertyName===null||i.propertyName.length===0)throw new Error("THREE.PropertyBinding: can not parse propertyName from trackName: "+e);return i}static findNode(e,t){if(t===void 0||t===""||t==="."||t===-1||t===e.name||t===e.uuid)return e;if(e.skeleton){let i=e.skeleton.getBoneByName(t);if(i!==void 0)return i}if(e.children){let i=function(s){for(let o=0;o<s.length;o++){let a=s[o];if(a.name===t||a.uuid===t)return a;let l=i(a.children);if(l)return l}return null},r=i(e.children);if(r)return r}return null}_getValue_unavailable(){}_setValue_unavailable(){}_getValue_direct(e,t){e[t]=this.targetObject[this.propertyName]}_getValue_array(e,t){let i=this.resolvedProperty;for(let r=0,s=i.length;r!==s;++r)e[t++]=i[r]}_getValue_arrayElement(e,t){e[t]=this.resolvedProperty[this.propertyIndex]}_getValue_toArray(e,t){this.resolvedProperty.toArray(e,t)}_setValue_direct(e,t){this.targetObject[this.propertyName]=e[t]}_setValue_direct_setNeedsUpdate(e,t){this.targetObject[this.propertyName]=e[t],this.targetObject.needsUpdate=!0}_setValue_direct_setMatrixWorldNeedsUpdate(e,t){this.targetObject[this.propertyName]=e[t],this.targetObject.matrixWorldNeedsUpdate=!0}_setValue_array(e,t){let i=this.resolvedProperty;for(let r=0,s=i.length;r!==s;++r)i[r]=e[t++]}_setValue_array_setNeedsUpdate(e,t){let i=this.resolvedProperty;for(let r=0,s=i.length;r!==s;++r)i[r]=e[t++];this.targetObject.needsUpdate=!0}_setValue_array_setMatrixWorldNeedsUpdate(e,t){let i=this.resolvedProperty;for(let r=0,s=i.length;r!==s;++r)i[r]=e[t++];this.targetObject.matrixWorldNeedsUpdate=!0}_setValue_arrayElement(e,t){this.resolvedProperty[this.propertyIndex]=e[t]}_setValue_arrayElement_setNeedsUpdate(e,t){this.resolvedProperty[this.propertyIndex]=e[t],this.targetObject.needsUpdate=!0}_setValue_arrayElement_setMatrixWorldNeedsUpdate(e,t){this.resolvedProperty[this.propertyIndex]=e[t],this.targetObject.matrixWorldNeedsUpdate=!0}_setValue_fromArray(e,t){this.resolvedProperty.fromArray(e,t)}_setValue_fromArray_setNeedsUpdate(e,t){this.resolvedProperty.fromArray(e,t),this.targetObject.needsUpdate=!0}_setValue_fromArray_setMatrixWorldNeedsUpdate(e,t){this.resolvedProperty.fromArray(e,t),this.targetObject.matrixWorldNeedsUpdate=!0}_getValue_unbound(e,t){this.bind(),this.getValue(e,t)}_setValue_unbound(e,t){this.bind(),this.setValue(e,t)}bind(){let e=this.node,t=this.parsedPath,i=t.objectName,r=t.propertyName,s=t.propertyIndex;if(e||(e=n.findNode(this.rootNode,t.nodeName),this.node=e),this.getValue=this._getValue_unavailable,this.setValue=this._setValue_unavailable,!e){$e("PropertyBinding: No target node found for track: "+this.path+".");return}if(i){let c=t.objectIndex;switch(i){case"materials":if(!e.material){et("PropertyBinding: Can not bind to material as node does not have a material.",this);return}if(!e.material.materials){et("PropertyBinding: Can not bind to material.materials as node.material does not have a materials array.",this);return}e=e.material.materials;break;case"bones":if(!e.skeleton){et("PropertyBinding: Can not bind to bones as node does not have a skeleton.",this);return}e=e.skeleton.bones;for(let u=0;u<e.length;u++)if(e[u].name===c){c=u;break}break;case"map":if("map"in e){e=e.map;break}if(!e.material){et("PropertyBinding: Can not bind to material as node does not have a material.",this);return}if(!e.material.map){et("PropertyBinding: Can not bind to material.map as node.material does not have a map.",this);return}e=e.material.map;break;default:if(e[i]===void 0){et("PropertyBinding: Can not bind to objectName of node undefined.",this);return}e=e[i]}if(c!==void 0){if(e[c]===void 0){et("PropertyBinding: Trying to bind to objectIndex of objectName, but is undefined.",this,e);return}e=e[c]}}let o=e[r];if(o===void 0){let c=t.nodeName;et("PropertyBinding: Trying to update property for track: "+c+"."+r+" but it wasn't found.",e);return}let a=this.Versioning.None;this.targetObject=e,e.isMaterial===!0?a=this.Versioning.NeedsUpdate:e.isObject3D===!0&&(a=this.Versioning.MatrixWorldNeedsUpdate);let l=this.BindingType.Direct;if(s!==void 0){if(r==="morphTargetInfluences"){if(!e.geometry){et("PropertyBinding: Can not bind to morphTargetInfluences because node does not have a geometry.",this);return}if(!e.geometry.morphAttributes){et("PropertyBinding: Can not bind to morphTargetInfluences because node does not have a geometry.morphAttributes.",this);return}e.morphTargetDictionary[s]!==void 0&&(s=e.morphTargetDictionary[s])}l=this.BindingType.ArrayElement,this.resolvedProperty=o,this.propertyIndex=s}else o.fromArray!==void 0&&o.toArray!==void 0?(l=this.BindingType.HasFromToArray,this.resolvedProperty=o):Array.isArray(o)?(l=this.BindingType.EntireArray,this.resolvedProperty=o):this.propertyName=r;this.getValue=this.GetterByBindingType[l],this.setValue=this.SetterByBindingTypeAndVersioning[l][a]}unbind(){this.node=null,this.getValue=this._getValue_unbound,this.setValue=this._setValue_unbound}};Jt.Composite=Up;Jt.prototype.BindingType={Direct:0,EntireArray:1,ArrayElement:2,HasFromToArray:3};Jt.prototype.Versioning={None:0,NeedsUpdate:1,MatrixWorldNeedsUpdate:2};Jt.prototype.GetterByBindingType=[Jt.prototype._getValue_direct,Jt.prototype._getValue_array,Jt.prototype._getValue_arrayElement,Jt.prototype._getValue_toArray];Jt.prototype.SetterByBindingTypeAndVersioning=[[Jt.prototype._setValue_direct,Jt.prototype._setValue_direct_setNeedsUpdate,Jt.prototype._setValue_direct_setMatrixWorldNeedsUpdate],[Jt.prototype._setValue_array,Jt.prototype._setValue_array_setNeedsUpdate,Jt.prototype._setValue_array_setMatrixWorldNeedsUpdate],[Jt.prototype._setValue_arrayElement,Jt.prototype._setValue_arrayElement_setNeedsUpdate,Jt.prototype._setValue_arrayElement_setMatrixWorldNeedsUpdate],[Jt.prototype._setValue_fromArray,Jt.prototype._setValue_fromArray_setNeedsUpdate,Jt.prototype._setValue_fromArray_setMatrixWorldNeedsUpdate]];var sU=new Float32Array(1);var cb=new Tt,Ml=class{constructor(e,t,i=0,r=1/0){this.ray=new us(e,t),this.near=i,this.far=r,this.camera=null,this.layers=new Zo,this.params={Mesh:{},Line:{threshold:1},LOD:{},Points:{threshold:1},Sprite:{}}}set(e,t){this.ray.set(e,t)}setFromCamera(e,t){t.isPerspectiveCamera?(this.ray.origin.setFromMatrixPosition(t.matrixWorld),this.ray.direction.set(e.x,e.y,.5).unproject(t).sub(this.ray.origin).normalize(),this.camera=t):t.isOrthographicCamera?(this.ray.origin.set(e.x,e.y,t.projectionMatrix.elements[14]).unproject(t),this.ray.direction.set(0,0,-1).transformDirection(t.matrixWorld),this.camera=t):et("Raycaster: Unsupported camera type: "+t.type)}setFromXRController(e){return cb.identity().extractRotation(e.matrixWorld),this.ray.origin.setFromMatrixPosition(e.matrixWorld),this.ray.direction.set(0,0,-1).applyMatrix4(cb),this}intersectObject(e,t=!0,i=[]){return Op(e,this,i,t),i.sort(ub),i}intersectObjects(e,t=!0,i=[]){for(let r=0,s=e.length;r<s;r++)Op(e[r],this,i,t);return i.sort(ub),i}};function ub(n,e){return n.distance-e.distance}function Op(n,e,t,i){let r=!0;if(n.layers.test(e.layers)&&n.raycast(e,t)===!1&&(r=!1),r===!0&&i===!0){let s=n.children;for(let o=0,a=s.length;o<a;o++)Op(s[o],e,t,!0)}}var jo=class{constructor(e=1,t=0,i=0){this.radius=e,this.phi=t,this.theta=i}set(e,t,i){return this.radius=e,this.phi=t,this.theta=i,this}copy(e){return this.radius=e.radius,this.phi=e.phi,this.theta=e.theta,this}makeSafe(){return this.phi=_t(this.phi,1e-6,Math.PI-1e-6),this}setFromVector3(e){return this.setFromCartesianCoords(e.x,e.y,e.z)}setFromCartesianCoords(e,t,i){return this.radius=Math.sqrt(e*e+t*t+i*i),this.radius===0?(this.theta=0,this.phi=0):(this.theta=Math.atan2(e,i),this.phi=Math.acos(_t(t/this.radius,-1,1))),this}clone(){return new this.constructor().copy(this)}};var Bp=class{static{this.prototype.isMatrix2=!0}constructor(e,t,i,r){this.elements=[1,0,0,1],e!==void 0&&this.set(e,t,i,r)}identity(){return this.set(1,0,0,1),this}fromArray(e,t=0){for(let i=0;i<4;i++)this.elements[i]=e[i+t];return this}set(e,t,i,r){let s=this.elements;return s[0]=e,s[2]=t,s[1]=i,s[3]=r,this}};var wl=class extends qi{constructor(e,t=null){super(),this.object=e,this.domElement=t,this.enabled=!0,this.state=-1,this.keys={},this.mouseButtons={LEFT:null,MIDDLE:null,RIGHT:null},this.touches={ONE:null,TWO:null}}connect(e){this.domElement!==null&&this.disconnect(),this.domElement=e}disconnect(){}dispose(){}update(){}};function gm(n,e,t,i){let r=ZA(i);switch(t){case im:return n*e;case fh:return n*e/r.components*r.byteLength;case dh:return n*e/r.components*r.byteLength;case bs:return n*e*2/r.components*r.byteLength;case ph:return n*e*2/r.components*r.byteLength;case rm:return n*e*3/r.components*r.byteLength;case er:return n*e*4/r.components*r.byteLength;case mh:return n*e*4/r.components*r.byteLength;case Rl:case Il:return Math.floor((n+3)/4)*Math.floor((e+3)/4)*8;case Cl:case Nl:return Math.floor((n+3)/4)*Math.floor((e+3)/4)*16;case _h:case xh:return Math.max(n,16)*Math.max(e,8)/4;case gh:case yh:return Math.max(n,8)*Math.max(e,8)/2;case bh:case vh:case Eh:case Mh:return Math.floor((n+3)/4)*Math.floor((e+3)/4)*8;case Sh:case Pl:case wh:return Math.floor((n+3)/4)*Math.floor((e+3)/4)*16;case Th:return Math.floor((n+3)/4)*Math.floor((e+3)/4)*16;case Ah:return Math.floor((n+4)/5)*Math.floor((e+3)/4)*16;case Rh:return Math.floor((n+4)/5)*Math.floor((e+4)/5)*16;case Ih:return Math.floor((n+5)/6)*Math.floor((e+4)/5)*16;case Ch:return Math.floor((n+5)/6)*Math.floor((e+5)/6)*16;case Nh:return Math.floor((n+7)/8)*Math.floor((e+4)/5)*16;case Ph:return Math.floor((n+7)/8)*Math.floor((e+5)/6)*16;case Lh:return Math.floor((n+7)/8)*Math.floor((e+7)/8)*16;case Dh:return Math.floor((n+9)/10)*Math.floor((e+4)/5)*16;case Fh:return Math.floor((n+9)/10)*Math.floor((e+5)/6)*16;case Uh:return Math.floor((n+9)/10)*Math.floor((e+7)/8)*16;case Oh:return Math.floor((n+9)/10)*Math.floor((e+9)/10)*16;case Bh:return Math.floor((n+11)/12)*Math.floor((e+9)/10)*16;case kh:return Math.floor((n+11)/12)*Math.floor((e+11)/12)*16;case Vh:case Gh:case zh:return Math.ceil(n/4)*Math.ceil(e/4)*16;case Hh:case Wh:return Math.ceil(n/4)*Math.ceil(e/4)*8;case Ll:case Xh:return Math.ceil(n/4)*Math.ceil(e/4)*16}throw new Error(`Unable to determine texture byte length for ${t} format.`)}function ZA(n){switch(n){case li:case Qp:return{byteLength:1,components:1};case na:case em:case Qi:return{byteLength:2,components:1};case uh:case hh:return{byteLength:2,components:4};case ji:case ch:case Ui:return{byteLength:4,components:1};case tm:case nm:return{byteLength:4,components:3}}throw new Error(`THREE.TextureUtils: Unknown texture type ${n}.`)}typeof __THREE_DEVTOOLS__<"u"&&__THREE_DEVTOOLS__.dispatchEvent(new CustomEvent("register",{detail:{revision:"187"}}));typeof window<"u"&&(window.__THREE__?$e("WARNING: Multiple instances of Three.js being imported."):window.__THREE__="187");function vv(){let n=null,e=!1,t=null,i=null;function r(s,o){i=n.requestAnimationFrame(r),t(s,o)}return{start:function(){e!==!0&&t!==null&&n!==null&&(i=n.requestAnimationFrame(r),e=!0)},stop:function(){n!==null&&n.cancelAnimationFrame(i),e=!1},setAnimationLoop:function(s){t=s},setContext:function(s){n=s}}}function e1(n){let e=new WeakMap;function t(a,l){let c=a.array,u=a.usage,h=c.byteLength,f=n.createBuffer();n.bindBuffer(l,f),n.bufferData(l,c,u),a.onUploadCallback();let d;if(c instanceof Float32Array)d=n.FLOAT;else if(typeof Float16Array<"u"&&c instanceof Float16Array)d=n.HALF_FLOAT;else if(c instanceof Uint16Array)a.isFloat16BufferAttribute?d=n.HALF_FLOAT:d=n.UNSIGNED_SHORT;else if(c instanceof Int16Array)d=n.SHORT;else if(c instanceof Uint32Array)d=n.UNSIGNED_INT;else if(c instanceof Int32Array)d=n.INT;else if(c instanceof Int8Array)d=n.BYTE;else if(c instanceof Uint8Array)d=n.UNSIGNED_BYTE;else if(c instanceof Uint8ClampedArray)d=n.UNSIGNED_BYTE;else throw new Error("THREE.WebGLAttributes: Unsupported buffer data format: "+c);return{buffer:f,type:d,bytesPerElement:c.BYTES_PER_ELEMENT,version:a.version,size:h}}function i(a,l,c){let u=l.array,h=l.updateRanges;if(n.bindBuffer(c,a),h.length===0)n.bufferSubData(c,0,u);else{h.sort((d,p)=>d.start-p.start);let f=0;for(let d=1;d<h.length;d++){let p=h[f],x=h[d];x.start<=p.start+p.count+1?p.count=Math.max(p.count,x.start+x.count-p.start):(++f,h[f]=x)}h.length=f+1;for(let d=0,p=h.length;d<p;d++){let x=h[d];n.bufferSubData(c,x.start*u.BYTES_PER_ELEMENT,u,x.start,x.count)}l.clearUpdateRanges()}l.onUploadCallback()}function r(a){return a.isInterleavedBufferAttribute&&(a=a.data),e.get(a)}function s(a){a.isInterleavedBufferAttribute&&(a=a.data);let l=e.get(a);l&&(n.deleteBuffer(l.buffer),e.delete(a))}function o(a,l){if(a.isInterleavedBufferAttribute&&(a=a.data),a.isGLBufferAttribute){let u=e.get(a);(!u||u.version<a.version)&&e.set(a,{buffer:a.buffer,type:a.type,bytesPerElement:a.elementSize,version:a.version});return}let c=e.get(a);if(c===void 0)e.set(a,t(a,l));else if(c.version<a.version){if(c.size!==a.array.byteLength)throw new Error("THREE.WebGLAttributes: The size of the buffer attribute's array buffer does not match the original size. Resizing buffer attributes is not supported.");i(c.buffer,a,l),c.version=a.version}}return{get:r,remove:s,update:o}}var t1=`#ifdef USE_ALPHAHASH
	if ( diffuseColor.a < getAlphaHashThreshold( vPosition ) ) discard;
#endif`,n1=`#ifdef USE_ALPHAHASH
	const float ALPHA_HASH_SCALE = 0.05;
	float hash2D( vec2 value ) {
		return fract( 1.0e4 * sin( 17.0 * value.x + 0.1 * value.y ) * ( 0.1 + abs( sin( 13.0 * value.y + value.x ) ) ) );
	}
	float hash3D( vec3 value ) {
		return hash2D( vec2( hash2D( value.xy ), value.z ) );
	}
	float getAlphaHashThreshold( vec3 position ) {
		float maxDeriv = max(
			length( dFdx( position.xyz ) ),
			length( dFdy( position.xyz ) )
		);
		float pixScale = 1.0 / ( ALPHA_HASH_SCALE * maxDeriv );
		vec2 pixScales = vec2(
			exp2( floor( log2( pixScale ) ) ),
			exp2( ceil( log2( pixScale ) ) )
		);
		vec2 alpha = vec2(
			hash3D( floor( pixScales.x * position.xyz ) ),
			hash3D( floor( pixScales.y * position.xyz ) )
		);
		float lerpFactor = fract( log2( pixScale ) );
		float x = ( 1.0 - lerpFactor ) * alpha.x + lerpFactor * alpha.y;
		float a = min( lerpFactor, 1.0 - lerpFactor );
		vec3 cases = vec3(
			x * x / ( 2.0 * a * ( 1.0 - a ) ),
			( x - 0.5 * a ) / ( 1.0 - a ),
			1.0 - ( ( 1.0 - x ) * ( 1.0 - x ) / ( 2.0 * a * ( 1.0 - a ) ) )
		);
		float threshold = ( x < ( 1.0 - a ) )
			? ( ( x < a ) ? cases.x : cases.y )
			: cases.z;
		return clamp( threshold , 1.0e-6, 1.0 );
	}
#endif`,i1=`#ifdef USE_ALPHAMAP
	diffuseColor.a *= texture2D( alphaMap, vAlphaMapUv ).g;
#endif`,r1=`#ifdef USE_ALPHAMAP
	uniform sampler2D alphaMap;
#endif`,s1=`#ifdef USE_ALPHATEST
	#ifdef ALPHA_TO_COVERAGE
	diffuseColor.a = smoothstep( alphaTest, alphaTest + fwidth( diffuseColor.a ), diffuseColor.a );
	if ( diffuseColor.a == 0.0 ) discard;
	#else
	if ( diffuseColor.a < alphaTest ) discard;
	#endif
#endif`,o1=`#ifdef USE_ALPHATEST
	uniform float alphaTest;
#endif`,a1=`#ifdef USE_AOMAP
	float ambientOcclusion = ( texture2D( aoMap, vAoMapUv ).r - 1.0 ) * aoMapIntensity + 1.0;
	reflectedLight.indirectDiffuse *= ambientOcclusion;
	#if defined( USE_CLEARCOAT ) 
		clearcoatSpecularIndirect *= ambientOcclusion;
	#endif
	#if defined( USE_SHEEN ) 
		sheenSpecularIndirect *= ambientOcclusion;
	#endif
	#if defined( USE_ENVMAP ) && defined( STANDARD )
		float dotNV = saturate( dot( geometryNormal, geometryViewDir ) );
		reflectedLight.indirectSpecular *= computeSpecularOcclusion( dotNV, ambientOcclusion, material.roughness );
	#endif
#endif`,l1=`#ifdef USE_AOMAP
	uniform sampler2D aoMap;
	uniform float aoMapIntensity;
#endif`,c1=`#ifdef USE_BATCHING
	#if ! defined( GL_ANGLE_multi_draw )
	#define gl_DrawID _gl_DrawID
	uniform int _gl_DrawID;
	#endif
	uniform highp sampler2D batchingTexture;
	uniform highp usampler2D batchingIdTexture;
	mat4 getBatchingMatrix( const in float i ) {
		int size = textureSize( batchingTexture, 0 ).x;
		int j = int( i ) * 4;
		int x = j % size;
		int y = j / size;
		vec4 v1 = texelFetch( batchingTexture, ivec2( x, y ), 0 );
		vec4 v2 = texelFetch( batchingTexture, ivec2( x + 1, y ), 0 );
		vec4 v3 = texelFetch( batchingTexture, ivec2( x + 2, y ), 0 );
		vec4 v4 = texelFetch( batchingTexture, ivec2( x + 3, y ), 0 );
		return mat4( v1, v2, v3, v4 );
	}
	float getIndirectIndex( const in int i ) {
		int size = textureSize( batchingIdTexture, 0 ).x;
		int x = i % size;
		int y = i / size;
		return float( texelFetch( batchingIdTexture, ivec2( x, y ), 0 ).r );
	}
#endif
#ifdef USE_BATCHING_COLOR
	uniform sampler2D batchingColorTexture;
	vec4 getBatchingColor( const in float i ) {
		int size = textureSize( batchingColorTexture, 0 ).x;
		int j = int( i );
		int x = j % size;
		int y = j / size;
		return texelFetch( batchingColorTexture, ivec2( x, y ), 0 );
	}
#endif`,u1=`#ifdef USE_BATCHING
	mat4 batchingMatrix = getBatchingMatrix( getIndirectIndex( gl_DrawID ) );
#endif`,h1=`vec3 transformed = vec3( position );
#ifdef USE_ALPHAHASH
	vPosition = vec3( position );
#endif`,f1=`vec3 objectNormal = vec3( normal );
#ifdef USE_TANGENT
	vec3 objectTangent = vec3( tangent.xyz );
#endif`,d1=`float G_BlinnPhong_Implicit( ) {
	return 0.25;
}
float D_BlinnPhong( const in float shininess, const in float dotNH ) {
	return RECIPROCAL_PI * ( shininess * 0.5 + 1.0 ) * pow( dotNH, shininess );
}
vec3 BRDF_BlinnPhong( const in vec3 lightDir, const in vec3 viewDir, const in vec3 normal, const in vec3 specularColor, const in float shininess ) {
	vec3 halfDir = normalize( lightDir + viewDir );
	float dotNH = saturate( dot( normal, halfDir ) );
	float dotVH = saturate( dot( viewDir, halfDir ) );
	vec3 F = F_Schlick( specularColor, 1.0, dotVH );
	float G = G_BlinnPhong_Implicit( );
	float D = D_BlinnPhong( shininess, dotNH );
	return F * ( G * D );
} // validated`,p1=`#ifdef USE_IRIDESCENCE
	const mat3 XYZ_TO_REC709 = mat3(
		 3.2404542, -0.9692660,  0.0556434,
		-1.5371385,  1.8760108, -0.2040259,
		-0.4985314,  0.0415560,  1.0572252
	);
	vec3 Fresnel0ToIor( vec3 fresnel0 ) {
		vec3 sqrtF0 = sqrt( fresnel0 );
		return ( vec3( 1.0 ) + sqrtF0 ) / ( vec3( 1.0 ) - sqrtF0 );
	}
	vec3 IorToFresnel0( vec3 transmittedIor, float incidentIor ) {
		return pow2( ( transmittedIor - vec3( incidentIor ) ) / ( transmittedIor + vec3( incidentIor ) ) );
	}
	float IorToFresnel0( float transmittedIor, float incidentIor ) {
		return pow2( ( transmittedIor - incidentIor ) / ( transmittedIor + incidentIor ));
	}
	vec3 evalSensitivity( float OPD, vec3 shift ) {
		float phase = 2.0 * PI * OPD * 1.0e-9;
		vec3 val = vec3( 5.4856e-13, 4.4201e-13, 5.2481e-13 );
		vec3 pos = vec3( 1.6810e+06, 1.7953e+06, 2.2084e+06 );
		vec3 var = vec3( 4.3278e+09, 9.3046e+09, 6.6121e+09 );
		vec3 xyz = val * sqrt( 2.0 * PI * var ) * cos( pos * phase + shift ) * exp( - pow2( phase ) * var );
		xyz.x += 9.7470e-14 * sqrt( 2.0 * PI * 4.5282e+09 ) * cos( 2.2399e+06 * phase + shift[ 0 ] ) * exp( - 4.5282e+09 * pow2( phase ) );
		xyz /= 1.0685e-7;
		vec3 rgb = XYZ_TO_REC709 * xyz;
		return rgb;
	}
	vec3 evalIridescence( float outsideIOR, float eta2, float cosTheta1, float thinFilmThickness, vec3 baseF0 ) {
		vec3 I;
		float iridescenceIOR = mix( outsideIOR, eta2, smoothstep( 0.0, 0.03, thinFilmThickness ) );
		float sinTheta2Sq = pow2( outsideIOR / iridescenceIOR ) * ( 1.0 - pow2( cosTheta1 ) );
		float cosTheta2Sq = 1.0 - sinTheta2Sq;
		if ( cosTheta2Sq < 0.0 ) {
			return vec3( 1.0 );
		}
		float cosTheta2 = sqrt( cosTheta2Sq );
		float R0 = IorToFresnel0( iridescenceIOR, outsideIOR );
		float R12 = F_Schlick( R0, 1.0, cosTheta1 );
		float T121 = 1.0 - R12;
		float phi12 = 0.0;
		if ( iridescenceIOR < outsideIOR ) phi12 = PI;
		float phi21 = PI - phi12;
		vec3 baseIOR = Fresnel0ToIor( clamp( baseF0, 0.0, 0.9999 ) );		vec3 R1 = IorToFresnel0( baseIOR, iridescenceIOR );
		vec3 R23 = F_Schlick( R1, 1.0, cosTheta2 );
		vec3 phi23 = vec3( 0.0 );
		if ( baseIOR[ 0 ] < iridescenceIOR ) phi23[ 0 ] = PI;
		if ( baseIOR[ 1 ] < iridescenceIOR ) phi23[ 1 ] = PI;
		if ( baseIOR[ 2 ] < iridescenceIOR ) phi23[ 2 ] = PI;
		float OPD = 2.0 * iridescenceIOR * thinFilmThickness * cosTheta2;
		vec3 phi = vec3( phi21 ) + phi23;
		vec3 R123 = clamp( R12 * R23, 1e-5, 0.9999 );
		vec3 r123 = sqrt( R123 );
		vec3 Rs = pow2( T121 ) * R23 / ( vec3( 1.0 ) - R123 );
		vec3 C0 = R12 + Rs;
		I = C0;
		vec3 Cm = Rs - T121;
		for ( int m = 1; m <= 2; ++ m ) {
			Cm *= r123;
			vec3 Sm = 2.0 * evalSensitivity( float( m ) * OPD, float( m ) * phi );
			I += Cm * Sm;
		}
		return max( I, vec3( 0.0 ) );
	}
#endif`,m1=`#ifdef USE_BUMPMAP
	uniform sampler2D bumpMap;
	uniform float bumpScale;
	vec2 dHdxy_fwd() {
		vec2 dSTdx = dFdx( vBumpMapUv );
		vec2 dSTdy = dFdy( vBumpMapUv );
		float Hll = bumpScale * texture2D( bumpMap, vBumpMapUv ).x;
		float dBx = bumpScale * texture2D( bumpMap, vBumpMapUv + dSTdx ).x - Hll;
		float dBy = bumpScale * texture2D( bumpMap, vBumpMapUv + dSTdy ).x - Hll;
		return vec2( dBx, dBy );
	}
	vec3 perturbNormalArb( vec3 surf_pos, vec3 surf_norm, vec2 dHdxy, float faceDirection ) {
		vec3 vSigmaX = normalize( dFdx( surf_pos.xyz ) );
		vec3 vSigmaY = normalize( dFdy( surf_pos.xyz ) );
		vec3 vN = surf_norm;
		vec3 R1 = cross( vSigmaY, vN );
		vec3 R2 = cross( vN, vSigmaX );
		float fDet = dot( vSigmaX, R1 ) * faceDirection;
		vec3 vGrad = sign( fDet ) * ( dHdxy.x * R1 + dHdxy.y * R2 );
		return normalize( abs( fDet ) * surf_norm - vGrad );
	}
#endif`,g1=`#if NUM_CLIPPING_PLANES > 0
	vec4 plane;
	#ifdef ALPHA_TO_COVERAGE
		float distanceToPlane, distanceGradient;
		float clipOpacity = 1.0;
		#pragma unroll_loop_start
		for ( int i = 0; i < UNION_CLIPPING_PLANES; i ++ ) {
			plane = clippingPlanes[ i ];
			distanceToPlane = - dot( vClipPosition, plane.xyz ) + plane.w;
			distanceGradient = fwidth( distanceToPlane ) / 2.0;
			clipOpacity *= smoothstep( - distanceGradient, distanceGradient, distanceToPlane );
			if ( clipOpacity == 0.0 ) discard;
		}
		#pragma unroll_loop_end
		#if UNION_CLIPPING_PLANES < NUM_CLIPPING_PLANES
			float unionClipOpacity = 1.0;
			#pragma unroll_loop_start
			for ( int i = UNION_CLIPPING_PLANES; i < NUM_CLIPPING_PLANES; i ++ ) {
				plane = clippingPlanes[ i ];
				distanceToPlane = - dot( vClipPosition, plane.xyz ) + plane.w;
				distanceGradient = fwidth( distanceToPlane ) / 2.0;
				unionClipOpacity *= 1.0 - smoothstep( - distanceGradient, distanceGradient, distanceToPlane );
			}
			#pragma unroll_loop_end
			clipOpacity *= 1.0 - unionClipOpacity;
		#endif
		diffuseColor.a *= clipOpacity;
		if ( diffuseColor.a == 0.0 ) discard;
	#else
		#pragma unroll_loop_start
		for ( int i = 0; i < UNION_CLIPPING_PLANES; i ++ ) {
			plane = clippingPlanes[ i ];
			if ( dot( vClipPosition, plane.xyz ) > plane.w ) discard;
		}
		#pragma unroll_loop_end
		#if UNION_CLIPPING_PLANES < NUM_CLIPPING_PLANES
			bool clipped = true;
			#pragma unroll_loop_start
			for ( int i = UNION_CLIPPING_PLANES; i < NUM_CLIPPING_PLANES; i ++ ) {
				plane = clippingPlanes[ i ];
				clipped = ( dot( vClipPosition, plane.xyz ) > plane.w ) && clipped;
			}
			#pragma unroll_loop_end
			if ( clipped ) discard;
		#endif
	#endif
#endif`,_1=`#if NUM_CLIPPING_PLANES > 0
	varying vec3 vClipPosition;
	uniform vec4 clippingPlanes[ NUM_CLIPPING_PLANES ];
#endif`,y1=`#if NUM_CLIPPING_PLANES > 0
	varying vec3 vClipPosition;
#endif`,x1=`#if NUM_CLIPPING_PLANES > 0
	vClipPosition = - mvPosition.xyz;
#endif`,b1=`#if defined( USE_COLOR ) || defined( USE_COLOR_ALPHA )
	diffuseColor *= vColor;
#endif`,v1=`#if defined( USE_COLOR ) || defined( USE_COLOR_ALPHA )
	varying vec4 vColor;
#endif`,S1=`#if defined( USE_COLOR ) || defined( USE_COLOR_ALPHA ) || defined( USE_INSTANCING_COLOR ) || defined( USE_BATCHING_COLOR )
	varying vec4 vColor;
#endif`,E1=`#if defined( USE_COLOR ) || defined( USE_COLOR_ALPHA ) || defined( USE_INSTANCING_COLOR ) || defined( USE_BATCHING_COLOR )
	vColor = vec4( 1.0 );
#endif
#ifdef USE_COLOR_ALPHA
	vColor *= color;
#elif defined( USE_COLOR )
	vColor.rgb *= color;
#endif
#ifdef USE_INSTANCING_COLOR
	vColor.rgb *= instanceColor.rgb;
#endif
#ifdef USE_BATCHING_COLOR
	vColor *= getBatchingColor( getIndirectIndex( gl_DrawID ) );
#endif`,M1=`#define PI 3.141592653589793
#define PI2 6.283185307179586
#define PI_HALF 1.5707963267948966
#define RECIPROCAL_PI 0.3183098861837907
#define RECIPROCAL_PI2 0.15915494309189535
#define EPSILON 1e-6
#ifndef saturate
#define saturate( a ) clamp( a, 0.0, 1.0 )
#endif
#define whiteComplement( a ) ( 1.0 - saturate( a ) )
float pow2( const in float x ) { return x*x; }
vec3 pow2( const in vec3 x ) { return x*x; }
float pow3( const in float x ) { return x*x*x; }
float pow4( const in float x ) { float x2 = x*x; return x2*x2; }
float max3( const in vec3 v ) { return max( max( v.x, v.y ), v.z ); }
float average( const in vec3 v ) { return dot( v, vec3( 0.3333333 ) ); }
highp float rand( const in vec2 uv ) {
	const highp float a = 12.9898, b = 78.233, c = 43758.5453;
	highp float dt = dot( uv.xy, vec2( a,b ) ), sn = mod( dt, PI );
	return fract( sin( sn ) * c );
}
#ifdef HIGH_PRECISION
	float precisionSafeLength( vec3 v ) { return length( v ); }
#else
	float precisionSafeLength( vec3 v ) {
		float maxComponent = max3( abs( v ) );
		return length( v / maxComponent ) * maxComponent;
	}
#endif
struct IncidentLight {
	vec3 color;
	vec3 direction;
	bool visible;
};
struct ReflectedLight {
	vec3 directDiffuse;
	vec3 directSpecular;
	vec3 indirectDiffuse;
	vec3 indirectSpecular;
};
#ifdef USE_ALPHAHASH
	varying vec3 vPosition;
#endif
vec3 transformDirection( in vec3 dir, in mat4 matrix ) {
	return normalize( ( matrix * vec4( dir, 0.0 ) ).xyz );
}
#define inverseTransformDirection transformDirectionByInverseViewMatrix
vec3 transformNormalByInverseViewMatrix( in vec3 normal, in mat4 viewMatrix ) {
	return normalize( ( vec4( normal, 0.0 ) * viewMatrix ).xyz );
}
vec3 transformDirectionByInverseViewMatrix( in vec3 dir, in mat4 viewMatrix ) {
	return normalize( ( vec4( dir, 0.0 ) * viewMatrix ).xyz );
}
bool isPerspectiveMatrix( mat4 m ) {
	return m[ 2 ][ 3 ] == - 1.0;
}
vec2 equirectUv( in vec3 dir ) {
	float u = atan( dir.z, dir.x ) * RECIPROCAL_PI2 + 0.5;
	float v = asin( clamp( dir.y, - 1.0, 1.0 ) ) * RECIPROCAL_PI + 0.5;
	return vec2( u, v );
}
vec3 BRDF_Lambert( const in vec3 diffuseColor ) {
	return RECIPROCAL_PI * diffuseColor;
}
vec3 F_Schlick( const in vec3 f0, const in float f90, const in float dotVH ) {
	float fresnel = exp2( ( - 5.55473 * dotVH - 6.98316 ) * dotVH );
	return f0 * ( 1.0 - fresnel ) + ( f90 * fresnel );
}
float F_Schlick( const in float f0, const in float f90, const in float dotVH ) {
	float fresnel = exp2( ( - 5.55473 * dotVH - 6.98316 ) * dotVH );
	return f0 * ( 1.0 - fresnel ) + ( f90 * fresnel );
} // validated`,w1=`vec3 transformedNormal = objectNormal;
#ifdef USE_TANGENT
	vec3 transformedTangent = objectTangent;
#endif
#ifdef USE_BATCHING
	mat3 bm = mat3( batchingMatrix );
	transformedNormal /= vec3( dot( bm[ 0 ], bm[ 0 ] ), dot( bm[ 1 ], bm[ 1 ] ), dot( bm[ 2 ], bm[ 2 ] ) );
	transformedNormal = bm * transformedNormal;
	#ifdef USE_TANGENT
		transformedTangent = bm * transformedTangent;
	#endif
#endif
#ifdef USE_INSTANCING
	mat3 im = mat3( instanceMatrix );
	transformedNormal /= vec3( dot( im[ 0 ], im[ 0 ] ), dot( im[ 1 ], im[ 1 ] ), dot( im[ 2 ], im[ 2 ] ) );
	transformedNormal = im * transformedNormal;
	#ifdef USE_TANGENT
		transformedTangent = im * transformedTangent;
	#endif
#endif
transformedNormal = normalMatrix * transformedNormal;
#ifdef FLIP_SIDED
	transformedNormal = - transformedNormal;
#endif
#ifdef USE_TANGENT
	transformedTangent = ( modelViewMatrix * vec4( transformedTangent, 0.0 ) ).xyz;
#endif`,T1=`#ifdef USE_DISPLACEMENTMAP
	uniform sampler2D displacementMap;
	uniform float displacementScale;
	uniform float displacementBias;
#endif`,A1=`#ifdef USE_DISPLACEMENTMAP
	transformed += normalize( objectNormal ) * ( texture2D( displacementMap, vDisplacementMapUv ).x * displacementScale + displacementBias );
#endif`,R1=`#ifdef USE_EMISSIVEMAP
	vec4 emissiveColor = texture2D( emissiveMap, vEmissiveMapUv );
	#ifdef DECODE_VIDEO_TEXTURE_EMISSIVE
		emissiveColor = sRGBTransferEOTF( emissiveColor );
	#endif
	totalEmissiveRadiance *= emissiveColor.rgb;
#endif`,I1=`#ifdef USE_EMISSIVEMAP
	uniform sampler2D emissiveMap;
#endif`,C1="gl_FragColor = linearToOutputTexel( gl_FragColor );",N1=`vec4 LinearTransferOETF( in vec4 value ) {
	return value;
}
vec4 sRGBTransferEOTF( in vec4 value ) {
	return vec4( mix( pow( value.rgb * 0.9478672986 + vec3( 0.0521327014 ), vec3( 2.4 ) ), value.rgb * 0.0773993808, vec3( lessThanEqual( value.rgb, vec3( 0.04045 ) ) ) ), value.a );
}
vec4 sRGBTransferOETF( in vec4 value ) {
	return vec4( mix( pow( value.rgb, vec3( 0.41666 ) ) * 1.055 - vec3( 0.055 ), value.rgb * 12.92, vec3( lessThanEqual( value.rgb, vec3( 0.0031308 ) ) ) ), value.a );
}`,P1=`#ifdef USE_ENVMAP
	#ifdef ENV_WORLDPOS
		vec3 cameraToFrag;
		if ( isOrthographic ) {
			cameraToFrag = normalize( vec3( - viewMatrix[ 0 ][ 2 ], - viewMatrix[ 1 ][ 2 ], - viewMatrix[ 2 ][ 2 ] ) );
		} else {
			cameraToFrag = normalize( vWorldPosition - cameraPosition );
		}
		vec3 worldNormal = transformNormalByInverseViewMatrix( normal, viewMatrix );
		#ifdef ENVMAP_MODE_REFLECTION
			vec3 reflectVec = reflect( cameraToFrag, worldNormal );
		#else
			vec3 reflectVec = refract( cameraToFrag, worldNormal, refractionRatio );
		#endif
	#else
		vec3 reflectVec = vReflect;
	#endif
	#ifdef ENVMAP_TYPE_CUBE
		vec4 envColor = textureCube( envMap, envMapRotation * reflectVec );
		#ifdef ENVMAP_BLENDING_MULTIPLY
			outgoingLight = mix( outgoingLight, outgoingLight * envColor.xyz, specularStrength * reflectivity );
		#elif defined( ENVMAP_BLENDING_MIX )
			outgoingLight = mix( outgoingLight, envColor.xyz, specularStrength * reflectivity );
		#elif defined( ENVMAP_BLENDING_ADD )
			outgoingLight += envColor.xyz * specularStrength * reflectivity;
		#endif
	#endif
#endif`,L1=`#ifdef USE_ENVMAP
	uniform float envMapIntensity;
	uniform mat3 envMapRotation;
	uniform samplerCube envMap;
	#ifdef ENVMAP_TYPE_PMREM
		float roughnessToMip( const in float roughness ) {
			float r = clamp( roughness, 0.0, 1.0 );
			return ENVMAP_MAX_LOD * r * ( 2.0 - r );
		}
	#endif
#endif`,D1=`#ifdef USE_ENVMAP
	uniform float reflectivity;
	#if defined( USE_BUMPMAP ) || defined( USE_NORMALMAP ) || defined( PHONG ) || defined( LAMBERT )
		#define ENV_WORLDPOS
	#endif
	#ifdef ENV_WORLDPOS
		varying vec3 vWorldPosition;
		uniform float refractionRatio;
	#else
		varying vec3 vReflect;
	#endif
#endif`,F1=`#ifdef USE_ENVMAP
	#if defined( USE_BUMPMAP ) || defined( USE_NORMALMAP ) || defined( PHONG ) || defined( LAMBERT )
		#define ENV_WORLDPOS
	#endif
	#ifdef ENV_WORLDPOS
		
		varying vec3 vWorldPosition;
	#else
		varying vec3 vReflect;
		uniform float refractionRatio;
	#endif
#endif`,U1=`#ifdef USE_ENVMAP
	#ifdef ENV_WORLDPOS
		vWorldPosition = worldPosition.xyz;
	#else
		vec3 cameraToVertex;
		if ( isOrthographic ) {
			cameraToVertex = normalize( vec3( - viewMatrix[ 0 ][ 2 ], - viewMatrix[ 1 ][ 2 ], - viewMatrix[ 2 ][ 2 ] ) );
		} else {
			cameraToVertex = normalize( worldPosition.xyz - cameraPosition );
		}
		vec3 worldNormal = transformNormalByInverseViewMatrix( transformedNormal, viewMatrix );
		#ifdef ENVMAP_MODE_REFLECTION
			vReflect = reflect( cameraToVertex, worldNormal );
		#else
			vReflect = refract( cameraToVertex, worldNormal, refractionRatio );
		#endif
	#endif
#endif`,O1=`#ifdef USE_FOG
	vFogDepth = - mvPosition.z;
#endif`,B1=`#ifdef USE_FOG
	varying float vFogDepth;
#endif`,k1=`#ifdef USE_FOG
	#ifdef FOG_EXP2
		float fogFactor = 1.0 - exp( - fogDensity * fogDensity * vFogDepth * vFogDepth );
	#else
		float fogFactor = smoothstep( fogNear, fogFar, vFogDepth );
	#endif
	gl_FragColor.rgb = mix( gl_FragColor.rgb, fogColor, fogFactor );
#endif`,V1=`#ifdef USE_FOG
	uniform vec3 fogColor;
	varying float vFogDepth;
	#ifdef FOG_EXP2
		uniform float fogDensity;
	#else
		uniform float fogNear;
		uniform float fogFar;
	#endif
#endif`,G1=`#ifdef USE_GRADIENTMAP
	uniform sampler2D gradientMap;
#endif
vec3 getGradientIrradiance( vec3 normal, vec3 lightDirection ) {
	float dotNL = dot( normal, lightDirection );
	vec2 coord = vec2( dotNL * 0.5 + 0.5, 0.0 );
	#ifdef USE_GRADIENTMAP
		return vec3( texture2D( gradientMap, coord ).r );
	#else
		vec2 fw = fwidth( coord ) * 0.5;
		return mix( vec3( 0.7 ), vec3( 1.0 ), smoothstep( 0.7 - fw.x, 0.7 + fw.x, coord.x ) );
	#endif
}`,z1=`#ifdef USE_LIGHTMAP
	uniform sampler2D lightMap;
	uniform float lightMapIntensity;
#endif`,H1=`LambertMaterial material;
material.diffuseColor = diffuseColor.rgb;
material.specularStrength = specularStrength;`,W1=`varying vec3 vViewPosition;
struct LambertMaterial {
	vec3 diffuseColor;
	float specularStrength;
};
void RE_Direct_Lambert( const in IncidentLight directLight, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in LambertMaterial material, inout ReflectedLight reflectedLight ) {
	float dotNL = saturate( dot( geometryNormal, directLight.direction ) );
	vec3 irradiance = dotNL * directLight.color;
	reflectedLight.directDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
void RE_IndirectDiffuse_Lambert( const in vec3 irradiance, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in LambertMaterial material, inout ReflectedLight reflectedLight ) {
	reflectedLight.indirectDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
#define RE_Direct				RE_Direct_Lambert
#define RE_IndirectDiffuse		RE_IndirectDiffuse_Lambert`,X1=`uniform bool receiveShadow;
uniform vec3 ambientLightColor;
#if defined( USE_LIGHT_PROBES )
	uniform vec3 lightProbe[ 9 ];
#endif
vec3 shGetIrradianceAt( in vec3 normal, in vec3 shCoefficients[ 9 ] ) {
	float x = normal.x, y = normal.y, z = normal.z;
	vec3 result = shCoefficients[ 0 ] * 0.886227;
	result += shCoefficients[ 1 ] * 2.0 * 0.511664 * y;
	result += shCoefficients[ 2 ] * 2.0 * 0.511664 * z;
	result += shCoefficients[ 3 ] * 2.0 * 0.511664 * x;
	result += shCoefficients[ 4 ] * 2.0 * 0.429043 * x * y;
	result += shCoefficients[ 5 ] * 2.0 * 0.429043 * y * z;
	result += shCoefficients[ 6 ] * ( 0.743125 * z * z - 0.247708 );
	result += shCoefficients[ 7 ] * 2.0 * 0.429043 * x * z;
	result += shCoefficients[ 8 ] * 0.429043 * ( x * x - y * y );
	return result;
}
vec3 getLightProbeIrradiance( const in vec3 lightProbe[ 9 ], const in vec3 normal ) {
	vec3 worldNormal = transformNormalByInverseViewMatrix( normal, viewMatrix );
	vec3 irradiance = shGetIrradianceAt( worldNormal, lightProbe );
	return irradiance;
}
vec3 getAmbientLightIrradiance( const in vec3 ambientLightColor ) {
	vec3 irradiance = ambientLightColor;
	return irradiance;
}
float getDistanceAttenuation( const in float lightDistance, const in float cutoffDistance, const in float decayExponent ) {
	float distanceFalloff = 1.0 / max( pow( lightDistance, decayExponent ), 0.01 );
	if ( cutoffDistance > 0.0 ) {
		distanceFalloff *= pow2( saturate( 1.0 - pow4( lightDistance / cutoffDistance ) ) );
	}
	return distanceFalloff;
}
float getSpotAttenuation( const in float coneCosine, const in float penumbraCosine, const in float angleCosine ) {
	return smoothstep( coneCosine, penumbraCosine, angleCosine );
}
#if NUM_SUN_LIGHTS > 0
	struct SunLight {
		vec3 direction;
		vec3 color;
	};
	uniform SunLight sunLights[ NUM_SUN_LIGHTS ];
	void getSunLightInfo( const in SunLight sunLight, out IncidentLight light ) {
		light.color = sunLight.color;
		light.direction = sunLight.direction;
		light.visible = true;
	}
#endif
#if NUM_DIR_LIGHTS > 0
	struct DirectionalLight {
		vec3 direction;
		vec3 color;
	};
	uniform DirectionalLight directionalLights[ NUM_DIR_LIGHTS ];
	void getDirectionalLightInfo( const in DirectionalLight directionalLight, out IncidentLight light ) {
		light.color = directionalLight.color;
		light.direction = directionalLight.direction;
		light.visible = true;
	}
#endif
#if NUM_POINT_LIGHTS > 0
	struct PointLight {
		vec3 position;
		vec3 color;
		float distance;
		float decay;
	};
	uniform PointLight pointLights[ NUM_POINT_LIGHTS ];
	void getPointLightInfo( const in PointLight pointLight, const in vec3 geometryPosition, out IncidentLight light ) {
		vec3 lVector = pointLight.position - geometryPosition;
		light.direction = normalize( lVector );
		float lightDistance = length( lVector );
		light.color = pointLight.color;
		light.color *= getDistanceAttenuation( lightDistance, pointLight.distance, pointLight.decay );
		light.visible = ( light.color != vec3( 0.0 ) );
	}
#endif
#if NUM_SPOT_LIGHTS > 0
	struct SpotLight {
		vec3 position;
		vec3 direction;
		vec3 color;
		float distance;
		float decay;
		float coneCos;
		float penumbraCos;
	};
	uniform SpotLight spotLights[ NUM_SPOT_LIGHTS ];
	void getSpotLightInfo( const in SpotLight spotLight, const in vec3 geometryPosition, out IncidentLight light ) {
		vec3 lVector = spotLight.position - geometryPosition;
		light.direction = normalize( lVector );
		float angleCos = dot( light.direction, spotLight.direction );
		float spotAttenuation = getSpotAttenuation( spotLight.coneCos, spotLight.penumbraCos, angleCos );
		if ( spotAttenuation > 0.0 ) {
			float lightDistance = length( lVector );
			light.color = spotLight.color * spotAttenuation;
			light.color *= getDistanceAttenuation( lightDistance, spotLight.distance, spotLight.decay );
			light.visible = ( light.color != vec3( 0.0 ) );
		} else {
			light.color = vec3( 0.0 );
			light.visible = false;
		}
	}
#endif
#if NUM_RECT_AREA_LIGHTS > 0
	struct RectAreaLight {
		vec3 color;
		vec3 position;
		vec3 halfWidth;
		vec3 halfHeight;
	};
	uniform sampler2D ltc_1;	uniform sampler2D ltc_2;
	uniform RectAreaLight rectAreaLights[ NUM_RECT_AREA_LIGHTS ];
#endif
#if NUM_HEMI_LIGHTS > 0
	struct HemisphereLight {
		vec3 direction;
		vec3 skyColor;
		vec3 groundColor;
	};
	uniform HemisphereLight hemisphereLights[ NUM_HEMI_LIGHTS ];
	vec3 getHemisphereLightIrradiance( const in HemisphereLight hemiLight, const in vec3 normal ) {
		float dotNL = dot( normal, hemiLight.direction );
		float hemiDiffuseWeight = 0.5 * dotNL + 0.5;
		vec3 irradiance = mix( hemiLight.groundColor, hemiLight.skyColor, hemiDiffuseWeight );
		return irradiance;
	}
#endif
#include <lightprobes_pars_fragment>`,Y1=`#ifdef USE_ENVMAP
	vec3 getIBLIrradiance( const in vec3 normal ) {
		#ifdef ENVMAP_TYPE_PMREM
			vec3 worldNormal = transformNormalByInverseViewMatrix( normal, viewMatrix );
			vec4 envMapColor = textureLod( envMap, envMapRotation * worldNormal, ENVMAP_MAX_LOD );
			return PI * envMapColor.rgb * envMapIntensity;
		#else
			return vec3( 0.0 );
		#endif
	}
	vec3 getIBLRadiance( const in vec3 viewDir, const in vec3 normal, const in float roughness ) {
		#ifdef ENVMAP_TYPE_PMREM
			vec3 reflectVec = reflect( - viewDir, normal );
			reflectVec = normalize( mix( reflectVec, normal, pow4( roughness ) ) );
			reflectVec = transformDirectionByInverseViewMatrix( reflectVec, viewMatrix );
			vec4 envMapColor = textureLod( envMap, envMapRotation * reflectVec, roughnessToMip( roughness ) );
			return envMapColor.rgb * envMapIntensity;
		#else
			return vec3( 0.0 );
		#endif
	}
	#ifdef USE_RETROREFLECTION
		vec3 getIBLRetroRadiance( const in vec3 viewDir, const in vec3 normal, const in float roughness ) {
			#ifdef ENVMAP_TYPE_PMREM
				vec3 retroVec = normalize( mix( viewDir, normal, pow4( roughness ) ) );
				retroVec = transformDirectionByInverseViewMatrix( retroVec, viewMatrix );
				vec4 envMapColor = textureLod( envMap, envMapRotation * retroVec, roughnessToMip( roughness ) );
				return envMapColor.rgb * envMapIntensity;
			#else
				return vec3( 0.0 );
			#endif
		}
	#endif
	#ifdef USE_ANISOTROPY
		vec3 getIBLAnisotropyRadiance( const in vec3 viewDir, const in vec3 normal, const in float roughness, const in vec3 bitangent, const in float anisotropy ) {
			#ifdef ENVMAP_TYPE_PMREM
				vec3 bentNormal = cross( bitangent, viewDir );
				bentNormal = normalize( cross( bentNormal, bitangent ) );
				bentNormal = normalize( mix( bentNormal, normal, pow2( pow2( 1.0 - anisotropy * ( 1.0 - roughness ) ) ) ) );
				return getIBLRadiance( viewDir, bentNormal, roughness );
			#else
				return vec3( 0.0 );
			#endif
		}
		#ifdef USE_RETROREFLECTION
			vec3 getIBLAnisotropyRetroRadiance( const in vec3 viewDir, const in vec3 normal, const in float roughness, const in vec3 bitangent, const in float anisotropy ) {
				#ifdef ENVMAP_TYPE_PMREM
					vec3 bentNormal = cross( bitangent, viewDir );
					bentNormal = normalize( cross( bentNormal, bitangent ) );
					bentNormal = normalize( mix( bentNormal, normal, pow2( pow2( 1.0 - anisotropy * ( 1.0 - roughness ) ) ) ) );
					return getIBLRetroRadiance( viewDir, bentNormal, roughness );
				#else
					return vec3( 0.0 );
				#endif
			}
		#endif
	#endif
#endif`,Z1=`ToonMaterial material;
material.diffuseColor = diffuseColor.rgb;`,K1=`varying vec3 vViewPosition;
struct ToonMaterial {
	vec3 diffuseColor;
};
void RE_Direct_Toon( const in IncidentLight directLight, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in ToonMaterial material, inout ReflectedLight reflectedLight ) {
	vec3 irradiance = getGradientIrradiance( geometryNormal, directLight.direction ) * directLight.color;
	reflectedLight.directDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
void RE_IndirectDiffuse_Toon( const in vec3 irradiance, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in ToonMaterial material, inout ReflectedLight reflectedLight ) {
	reflectedLight.indirectDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
#define RE_Direct				RE_Direct_Toon
#define RE_IndirectDiffuse		RE_IndirectDiffuse_Toon`,$1=`BlinnPhongMaterial material;
material.diffuseColor = diffuseColor.rgb;
material.specularColor = specular;
material.specularShininess = shininess;
material.specularStrength = specularStrength;`,q1=`varying vec3 vViewPosition;
struct BlinnPhongMaterial {
	vec3 diffuseColor;
	vec3 specularColor;
	float specularShininess;
	float specularStrength;
};
void RE_Direct_BlinnPhong( const in IncidentLight directLight, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in BlinnPhongMaterial material, inout ReflectedLight reflectedLight ) {
	float dotNL = saturate( dot( geometryNormal, directLight.direction ) );
	vec3 irradiance = dotNL * directLight.color;
	reflectedLight.directDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
	reflectedLight.directSpecular += irradiance * BRDF_BlinnPhong( directLight.direction, geometryViewDir, geometryNormal, material.specularColor, material.specularShininess ) * material.specularStrength;
}
void RE_IndirectDiffuse_BlinnPhong( const in vec3 irradiance, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in BlinnPhongMaterial material, inout ReflectedLight reflectedLight ) {
	reflectedLight.indirectDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
#define RE_Direct				RE_Direct_BlinnPhong
#define RE_IndirectDiffuse		RE_IndirectDiffuse_BlinnPhong`,J1=`PhysicalMaterial material;
material.diffuseColor = diffuseColor.rgb;
material.diffuseContribution = diffuseColor.rgb * ( 1.0 - metalnessFactor );
material.metalness = metalnessFactor;
vec3 dxy = max( abs( dFdx( nonPerturbedNormal ) ), abs( dFdy( nonPerturbedNormal ) ) );
float geometryRoughness = max( max( dxy.x, dxy.y ), dxy.z );
material.roughness = max( roughnessFactor, 0.045 );
material.roughness += geometryRoughness;
material.roughness = min( material.roughness, 1.0 );
#ifdef USE_DIFFUSE_ROUGHNESS
	float diffuseRoughnessFactor = diffuseRoughness;
	#ifdef USE_DIFFUSE_ROUGHNESSMAP
		diffuseRoughnessFactor *= texture2D( diffuseRoughnessMap, vDiffuseRoughnessMapUv ).r;
	#endif
	material.diffuseRoughness = saturate( diffuseRoughnessFactor );
#endif
#ifdef IOR
	material.ior = ior;
	#ifdef USE_SPECULAR
		float specularIntensityFactor = specularIntensity;
		vec3 specularColorFactor = specularColor;
		#ifdef USE_SPECULAR_COLORMAP
			specularColorFactor *= texture2D( specularColorMap, vSpecularColorMapUv ).rgb;
		#endif
		#ifdef USE_SPECULAR_INTENSITYMAP
			specularIntensityFactor *= texture2D( specularIntensityMap, vSpecularIntensityMapUv ).a;
		#endif
		material.specularF90 = mix( specularIntensityFactor, 1.0, metalnessFactor );
	#else
		float specularIntensityFactor = 1.0;
		vec3 specularColorFactor = vec3( 1.0 );
		material.specularF90 = 1.0;
	#endif
	material.specularColor = min( pow2( ( material.ior - 1.0 ) / ( material.ior + 1.0 ) ) * specularColorFactor, vec3( 1.0 ) ) * specularIntensityFactor;
	material.specularColorBlended = mix( material.specularColor, diffuseColor.rgb, metalnessFactor );
#else
	material.specularColor = vec3( 0.04 );
	material.specularColorBlended = mix( material.specularColor, diffuseColor.rgb, metalnessFactor );
	material.specularF90 = 1.0;
#endif
#ifdef USE_CLEARCOAT
	material.clearcoat = clearcoat;
	material.clearcoatRoughness = clearcoatRoughness;
	material.clearcoatF0 = vec3( 0.04 );
	material.clearcoatF90 = 1.0;
	#ifdef USE_CLEARCOATMAP
		material.clearcoat *= texture2D( clearcoatMap, vClearcoatMapUv ).x;
	#endif
	#ifdef USE_CLEARCOAT_ROUGHNESSMAP
		material.clearcoatRoughness *= texture2D( clearcoatRoughnessMap, vClearcoatRoughnessMapUv ).y;
	#endif
	material.clearcoat = saturate( material.clearcoat );	material.clearcoatRoughness = max( material.clearcoatRoughness, 0.045 );
	material.clearcoatRoughness += geometryRoughness;
	material.clearcoatRoughness = min( material.clearcoatRoughness, 1.0 );
#endif
#ifdef USE_DISPERSION
	material.dispersion = dispersion;
#endif
#ifdef USE_RETROREFLECTION
	material.retroreflectivity = retroreflectivity;
#endif
#ifdef USE_IRIDESCENCE
	material.iridescence = iridescence;
	material.iridescenceIOR = iridescenceIOR;
	#ifdef USE_IRIDESCENCEMAP
		material.iridescence *= texture2D( iridescenceMap, vIridescenceMapUv ).r;
	#endif
	#ifdef USE_IRIDESCENCE_THICKNESSMAP
		material.iridescenceThickness = (iridescenceThicknessMaximum - iridescenceThicknessMinimum) * texture2D( iridescenceThicknessMap, vIridescenceThicknessMapUv ).g + iridescenceThicknessMinimum;
	#else
		material.iridescenceThickness = iridescenceThicknessMaximum;
	#endif
#endif
#ifdef USE_SHEEN
	material.sheenColor = sheenColor;
	#ifdef USE_SHEEN_COLORMAP
		material.sheenColor *= texture2D( sheenColorMap, vSheenColorMapUv ).rgb;
	#endif
	material.sheenRoughness = clamp( sheenRoughness, 0.0001, 1.0 );
	#ifdef USE_SHEEN_ROUGHNESSMAP
		material.sheenRoughness *= texture2D( sheenRoughnessMap, vSheenRoughnessMapUv ).a;
	#endif
#endif
#ifdef USE_ANISOTROPY
	#ifdef USE_ANISOTROPYMAP
		mat2 anisotropyMat = mat2( anisotropyVector.x, anisotropyVector.y, - anisotropyVector.y, anisotropyVector.x );
		vec3 anisotropyPolar = texture2D( anisotropyMap, vAnisotropyMapUv ).rgb;
		vec2 anisotropyV = anisotropyMat * normalize( 2.0 * anisotropyPolar.rg - vec2( 1.0 ) ) * anisotropyPolar.b;
	#else
		vec2 anisotropyV = anisotropyVector;
	#endif
	material.anisotropy = length( anisotropyV );
	if( material.anisotropy == 0.0 ) {
		anisotropyV = vec2( 1.0, 0.0 );
	} else {
		anisotropyV /= material.anisotropy;
		material.anisotropy = saturate( material.anisotropy );
	}
	material.alphaT = mix( pow2( material.roughness ), 1.0, pow2( material.anisotropy ) );
	material.anisotropyT = tbn[ 0 ] * anisotropyV.x + tbn[ 1 ] * anisotropyV.y;
	material.anisotropyB = tbn[ 1 ] * anisotropyV.x - tbn[ 0 ] * anisotropyV.y;
#endif`,j1=`uniform sampler2D dfgLUT;
struct PhysicalMaterial {
	vec3 diffuseColor;
	vec3 diffuseContribution;
	vec3 specularColor;
	vec3 specularColorBlended;
	float roughness;
	float metalness;
	float specularF90;
	float dispersion;
	vec2 dfg;
	vec3 multiScatteringCompensation;
	#ifdef USE_DIFFUSE_ROUGHNESS
		float diffuseRoughness;
	#endif
	#ifdef USE_RETROREFLECTION
		float retroreflectivity;
	#endif
	#ifdef USE_CLEARCOAT
		float clearcoat;
		float clearcoatRoughness;
		vec3 clearcoatF0;
		float clearcoatF90;
	#endif
	#ifdef USE_IRIDESCENCE
		float iridescence;
		float iridescenceIOR;
		float iridescenceThickness;
		vec3 iridescenceFresnel;
		vec3 iridescenceF0Dielectric;
		vec3 iridescenceF0Metallic;
	#endif
	#ifdef USE_SHEEN
		vec3 sheenColor;
		float sheenRoughness;
	#endif
	#ifdef IOR
		float ior;
	#endif
	#ifdef USE_TRANSMISSION
		float transmission;
		float transmissionAlpha;
		float thickness;
		float attenuationDistance;
		vec3 attenuationColor;
	#endif
	#ifdef USE_ANISOTROPY
		float anisotropy;
		float alphaT;
		vec3 anisotropyT;
		vec3 anisotropyB;
	#endif
};
vec3 clearcoatSpecularDirect = vec3( 0.0 );
vec3 clearcoatSpecularIndirect = vec3( 0.0 );
vec3 sheenSpecularDirect = vec3( 0.0 );
vec3 sheenSpecularIndirect = vec3(0.0 );
vec3 Schlick_to_F0( const in vec3 f, const in float f90, const in float dotVH ) {
    float x = clamp( 1.0 - dotVH, 0.0, 1.0 );
    float x2 = x * x;
    float x5 = clamp( x * x2 * x2, 0.0, 0.9999 );
    return ( f - vec3( f90 ) * x5 ) / ( 1.0 - x5 );
}
#ifdef USE_DIFFUSE_ROUGHNESS
	const float EON_EPSILON = 1e-7;
	float FON_DirectionalAlbedo( const in float mu, const in float roughness, const in float A ) {
		float muComp = 1.0 - mu;
		float gOverPi = muComp * ( 0.0571085289 + muComp * ( 0.491881867 + muComp * ( - 0.332181442 + muComp * 0.0714429953 ) ) );
		return A * ( 1.0 + roughness * gOverPi );
	}
	vec3 BRDF_EON( const in vec3 lightDir, const in vec3 viewDir, const in vec3 normal, const in vec3 diffuseColor, const in float roughness ) {
		vec3 rho = saturate( diffuseColor );
		if ( roughness <= EON_EPSILON ) return BRDF_Lambert( rho );
		float dotNL = saturate( dot( normal, lightDir ) );
		float dotNV = saturate( dot( normal, viewDir ) );
		float s = dot( lightDir, viewDir ) - dotNL * dotNV;
		float sOverT = ( s > 0.0 ) ? s / max( max( dotNL, dotNV ), EON_EPSILON ) : s;
		float A = 1.0 / ( 1.0 + ( 0.5 - 2.0 / ( 3.0 * PI ) ) * roughness );
		vec3 singleScatter = rho * RECIPROCAL_PI * A * ( 1.0 + roughness * sOverT );
		float averageAlbedo = A * ( 1.0 + ( 2.0 / 3.0 - 28.0 / ( 15.0 * PI ) ) * roughness );
		float albedoV = FON_DirectionalAlbedo( dotNV, roughness, A );
		float albedoL = FON_DirectionalAlbedo( dotNL, roughness, A );
		vec3 rhoMultiScatter = rho * rho * averageAlbedo / max( vec3( EON_EPSILON ), vec3( 1.0 ) - rho * ( 1.0 - averageAlbedo ) );
		vec3 multiScatter = rhoMultiScatter * RECIPROCAL_PI
			* max( EON_EPSILON, 1.0 - albedoV )
			* max( EON_EPSILON, 1.0 - albedoL )
			/ max( EON_EPSILON, 1.0 - averageAlbedo );
		return singleScatter + multiScatter;
	}
	vec3 EON_DirectionalAlbedo( const in vec3 diffuseColor, const in float roughness, const in float dotNV ) {
		vec3 rho = saturate( diffuseColor );
		if ( roughness <= EON_EPSILON ) return rho;
		float A = 1.0 / ( 1.0 + ( 0.5 - 2.0 / ( 3.0 * PI ) ) * roughness );
		float directionalAlbedo = FON_DirectionalAlbedo( dotNV, roughness, A );
		float averageAlbedo = A * ( 1.0 + ( 2.0 / 3.0 - 28.0 / ( 15.0 * PI ) ) * roughness );
		vec3 rhoMultiScatter = rho * rho * averageAlbedo / max( vec3( EON_EPSILON ), vec3( 1.0 ) - rho * ( 1.0 - averageAlbedo ) );
		return rho * directionalAlbedo + rhoMultiScatter * ( 1.0 - directionalAlbedo );
	}
#endif
float V_GGX_SmithCorrelated( const in float alpha, const in float dotNL, const in float dotNV ) {
	float a2 = pow2( alpha );
	float gv = dotNL * sqrt( a2 + ( 1.0 - a2 ) * pow2( dotNV ) );
	float gl = dotNV * sqrt( a2 + ( 1.0 - a2 ) * pow2( dotNL ) );
	return 0.5 / max( gv + gl, EPSILON );
}
float D_GGX( const in float alpha, const in float dotNH ) {
	float a2 = pow2( alpha );
	float denom = pow2( dotNH ) * ( a2 - 1.0 ) + 1.0;
	return RECIPROCAL_PI * a2 / pow2( denom );
}
#ifdef USE_ANISOTROPY
	float V_GGX_SmithCorrelated_Anisotropic( const in float alphaT, const in float alphaB, const in float dotTV, const in float dotBV, const in float dotTL, const in float dotBL, const in float dotNV, const in float dotNL ) {
		float gv = dotNL * length( vec3( alphaT * dotTV, alphaB * dotBV, dotNV ) );
		float gl = dotNV * length( vec3( alphaT * dotTL, alphaB * dotBL, dotNL ) );
		return 0.5 / max( gv + gl, EPSILON );
	}
	float D_GGX_Anisotropic( const in float alphaT, const in float alphaB, const in float dotNH, const in float dotTH, const in float dotBH ) {
		float a2 = alphaT * alphaB;
		highp vec3 v = vec3( alphaB * dotTH, alphaT * dotBH, a2 * dotNH );
		highp float v2 = dot( v, v );
		float w2 = a2 / v2;
		return RECIPROCAL_PI * a2 * pow2 ( w2 );
	}
#endif
#ifdef USE_CLEARCOAT
	vec3 BRDF_GGX_Clearcoat( const in vec3 lightDir, const in vec3 viewDir, const in vec3 normal, const in PhysicalMaterial material) {
		vec3 f0 = material.clearcoatF0;
		float f90 = material.clearcoatF90;
		float roughness = max( material.clearcoatRoughness, 0.045 );
		float alpha = pow2( roughness );
		vec3 halfDir = normalize( lightDir + viewDir );
		float dotNL = saturate( dot( normal, lightDir ) );
		float dotNV = saturate( dot( normal, viewDir ) );
		float dotNH = saturate( dot( normal, halfDir ) );
		float dotVH = saturate( dot( viewDir, halfDir ) );
		vec3 F = F_Schlick( f0, f90, dotVH );
		float V = V_GGX_SmithCorrelated( alpha, dotNL, dotNV );
		float D = D_GGX( alpha, dotNH );
		return F * ( V * D );
	}
#endif
vec3 BRDF_GGX( const in vec3 lightDir, const in vec3 viewDir, const in vec3 normal, const in PhysicalMaterial material ) {
	vec3 f0 = material.specularColorBlended;
	float f90 = material.specularF90;
	float roughness = max( material.roughness, 0.045 );
	float alpha = pow2( roughness );
	vec3 halfDir = normalize( lightDir + viewDir );
	float dotNL = saturate( dot( normal, lightDir ) );
	float dotNV = saturate( dot( normal, viewDir ) );
	float dotNH = saturate( dot( normal, halfDir ) );
	float dotVH = saturate( dot( viewDir, halfDir ) );
	vec3 F = F_Schlick( f0, f90, dotVH );
	#ifdef USE_IRIDESCENCE
		F = mix( F, material.iridescenceFresnel, material.iridescence );
	#endif
	#ifdef USE_ANISOTROPY
		float dotTL = dot( material.anisotropyT, lightDir );
		float dotTV = dot( material.anisotropyT, viewDir );
		float dotTH = dot( material.anisotropyT, halfDir );
		float dotBL = dot( material.anisotropyB, lightDir );
		float dotBV = dot( material.anisotropyB, viewDir );
		float dotBH = dot( material.anisotropyB, halfDir );
		float alphaT = max( material.alphaT, alpha );
		float V = V_GGX_SmithCorrelated_Anisotropic( alphaT, alpha, dotTV, dotBV, dotTL, dotBL, dotNV, dotNL );
		float D = D_GGX_Anisotropic( alphaT, alpha, dotNH, dotTH, dotBH );
	#else
		float V = V_GGX_SmithCorrelated( alpha, dotNL, dotNV );
		float D = D_GGX( alpha, dotNH );
	#endif
	return F * ( V * D );
}
vec2 LTC_Uv( const in vec3 N, const in vec3 V, const in float roughness ) {
	const float LUT_SIZE = 64.0;
	const float LUT_SCALE = ( LUT_SIZE - 1.0 ) / LUT_SIZE;
	const float LUT_BIAS = 0.5 / LUT_SIZE;
	float dotNV = saturate( dot( N, V ) );
	vec2 uv = vec2( roughness, sqrt( 1.0 - dotNV ) );
	uv = uv * LUT_SCALE + LUT_BIAS;
	return uv;
}
float LTC_ClippedSphereFormFactor( const in vec3 f ) {
	float l = length( f );
	return max( ( l * l + f.z ) / ( l + 1.0 ), 0.0 );
}
vec3 LTC_EdgeVectorFormFactor( const in vec3 v1, const in vec3 v2 ) {
	float x = dot( v1, v2 );
	float y = abs( x );
	float a = 0.8543985 + ( 0.4965155 + 0.0145206 * y ) * y;
	float b = 3.4175940 + ( 4.1616724 + y ) * y;
	float v = a / b;
	float theta_sintheta = ( x > 0.0 ) ? v : 0.5 * inversesqrt( max( 1.0 - x * x, 1e-7 ) ) - v;
	return cross( v1, v2 ) * theta_sintheta;
}
vec3 LTC_Evaluate( const in vec3 N, const in vec3 V, const in vec3 P, const in mat3 mInv, const in vec3 rectCoords[ 4 ] ) {
	vec3 v1 = rectCoords[ 1 ] - rectCoords[ 0 ];
	vec3 v2 = rectCoords[ 3 ] - rectCoords[ 0 ];
	vec3 lightNormal = cross( v1, v2 );
	if( dot( lightNormal, P - rectCoords[ 0 ] ) < 0.0 ) return vec3( 0.0 );
	vec3 T1, T2;
	T1 = normalize( V - N * dot( V, N ) );
	T2 = - cross( N, T1 );
	mat3 mat = mInv * transpose( mat3( T1, T2, N ) );
	vec3 coords[ 4 ];
	coords[ 0 ] = mat * ( rectCoords[ 0 ] - P );
	coords[ 1 ] = mat * ( rectCoords[ 1 ] - P );
	coords[ 2 ] = mat * ( rectCoords[ 2 ] - P );
	coords[ 3 ] = mat * ( rectCoords[ 3 ] - P );
	coords[ 0 ] = normalize( coords[ 0 ] );
	coords[ 1 ] = normalize( coords[ 1 ] );
	coords[ 2 ] = normalize( coords[ 2 ] );
	coords[ 3 ] = normalize( coords[ 3 ] );
	vec3 vectorFormFactor = vec3( 0.0 );
	vectorFormFactor += LTC_EdgeVectorFormFactor( coords[ 0 ], coords[ 1 ] );
	vectorFormFactor += LTC_EdgeVectorFormFactor( coords[ 1 ], coords[ 2 ] );
	vectorFormFactor += LTC_EdgeVectorFormFactor( coords[ 2 ], coords[ 3 ] );
	vectorFormFactor += LTC_EdgeVectorFormFactor( coords[ 3 ], coords[ 0 ] );
	float result = LTC_ClippedSphereFormFactor( vectorFormFactor );
	return vec3( result );
}
#if defined( USE_SHEEN )
float D_Charlie( float roughness, float dotNH ) {
	float alpha = pow2( roughness );
	float invAlpha = 1.0 / alpha;
	float cos2h = dotNH * dotNH;
	float sin2h = max( 1.0 - cos2h, 0.0078125 );
	return ( 2.0 + invAlpha ) * pow( sin2h, invAlpha * 0.5 ) / ( 2.0 * PI );
}
float V_Neubelt( float dotNV, float dotNL ) {
	return saturate( 1.0 / ( 4.0 * ( dotNL + dotNV - dotNL * dotNV ) ) );
}
vec3 BRDF_Sheen( const in vec3 lightDir, const in vec3 viewDir, const in vec3 normal, vec3 sheenColor, const in float sheenRoughness ) {
	vec3 halfDir = normalize( lightDir + viewDir );
	float dotNL = saturate( dot( normal, lightDir ) );
	float dotNV = saturate( dot( normal, viewDir ) );
	float dotNH = saturate( dot( normal, halfDir ) );
	float D = D_Charlie( sheenRoughness, dotNH );
	float V = V_Neubelt( dotNV, dotNL );
	return sheenColor * ( D * V );
}
#endif
float IBLSheenBRDF( const in vec3 normal, const in vec3 viewDir, const in float roughness ) {
	float dotNV = saturate( dot( normal, viewDir ) );
	float r2 = roughness * roughness;
	float rInv = 1.0 / ( roughness + 0.1 );
	float a = -1.9362 + 1.0678 * roughness + 0.4573 * r2 - 0.8469 * rInv;
	float b = -0.6014 + 0.5538 * roughness - 0.4670 * r2 - 0.1255 * rInv;
	float DG = exp( a * dotNV + b );
	return saturate( DG );
}
vec3 EnvironmentBRDF( const in vec3 normal, const in vec3 viewDir, const in vec3 specularColor, const in float specularF90, const in float roughness ) {
	float dotNV = saturate( dot( normal, viewDir ) );
	vec2 fab = texture2D( dfgLUT, vec2( roughness, dotNV ) ).rg;
	return specularColor * fab.x + specularF90 * fab.y;
}
#ifdef USE_IRIDESCENCE
void computeMultiscatteringIridescence( const in vec2 fab, const in vec3 specularColor, const in float specularF90, const in float iridescence, const in vec3 iridescenceF0, inout vec3 singleScatter, inout vec3 multiScatter ) {
#else
void computeMultiscattering( const in vec2 fab, const in vec3 specularColor, const in float specularF90, inout vec3 singleScatter, inout vec3 multiScatter ) {
#endif
	#ifdef USE_IRIDESCENCE
		vec3 Fr = mix( specularColor, iridescenceF0, iridescence );
	#else
		vec3 Fr = specularColor;
	#endif
	vec3 FssEss = Fr * fab.x + specularF90 * fab.y;
	float Ess = fab.x + fab.y;
	float Ems = 1.0 - Ess;
	vec3 Favg = Fr + ( 1.0 - Fr ) * 0.047619;	vec3 Fms = FssEss * Favg / ( 1.0 - Ems * Favg );
	singleScatter += FssEss;
	multiScatter += Fms * Ems;
}
#if NUM_RECT_AREA_LIGHTS > 0
	void RE_Direct_RectArea_Physical( const in RectAreaLight rectAreaLight, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in PhysicalMaterial material, inout ReflectedLight reflectedLight ) {
		vec3 normal = geometryNormal;
		vec3 viewDir = geometryViewDir;
		vec3 position = geometryPosition;
		vec3 lightPos = rectAreaLight.position;
		vec3 halfWidth = rectAreaLight.halfWidth;
		vec3 halfHeight = rectAreaLight.halfHeight;
		vec3 lightColor = rectAreaLight.color;
		float roughness = material.roughness;
		vec3 rectCoords[ 4 ];
		rectCoords[ 0 ] = lightPos + halfWidth - halfHeight;		rectCoords[ 1 ] = lightPos - halfWidth - halfHeight;
		rectCoords[ 2 ] = lightPos - halfWidth + halfHeight;
		rectCoords[ 3 ] = lightPos + halfWidth + halfHeight;
		vec2 uv = LTC_Uv( normal, viewDir, roughness );
		vec4 t1 = texture2D( ltc_1, uv );
		vec4 t2 = texture2D( ltc_2, uv );
		mat3 mInv = mat3(
			vec3( t1.x, 0, t1.y ),
			vec3(    0, 1,    0 ),
			vec3( t1.z, 0, t1.w )
		);
		vec3 fresnel = ( material.specularColorBlended * t2.x + ( material.specularF90 - material.specularColorBlended ) * t2.y );
		reflectedLight.directSpecular += lightColor * fresnel * LTC_Evaluate( normal, viewDir, position, mInv, rectCoords );
		reflectedLight.directDiffuse += lightColor * material.diffuseContribution * LTC_Evaluate( normal, viewDir, position, mat3( 1.0 ), rectCoords );
		#ifdef USE_CLEARCOAT
			vec3 Ncc = geometryClearcoatNormal;
			vec2 uvClearcoat = LTC_Uv( Ncc, viewDir, material.clearcoatRoughness );
			vec4 t1Clearcoat = texture2D( ltc_1, uvClearcoat );
			vec4 t2Clearcoat = texture2D( ltc_2, uvClearcoat );
			mat3 mInvClearcoat = mat3(
				vec3( t1Clearcoat.x, 0, t1Clearcoat.y ),
				vec3(             0, 1,             0 ),
				vec3( t1Clearcoat.z, 0, t1Clearcoat.w )
			);
			vec3 fresnelClearcoat = material.clearcoatF0 * t2Clearcoat.x + ( material.clearcoatF90 - material.clearcoatF0 ) * t2Clearcoat.y;
			clearcoatSpecularDirect += lightColor * fresnelClearcoat * LTC_Evaluate( Ncc, viewDir, position, mInvClearcoat, rectCoords );
		#endif
	}
#endif
void RE_Direct_Physical( const in IncidentLight directLight, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in PhysicalMaterial material, inout ReflectedLight reflectedLight ) {
	float dotNL = saturate( dot( geometryNormal, directLight.direction ) );
	vec3 irradiance = dotNL * directLight.color;
	#ifdef USE_CLEARCOAT
		float dotNLcc = saturate( dot( geometryClearcoatNormal, directLight.direction ) );
		vec3 ccIrradiance = dotNLcc * directLight.color;
		clearcoatSpecularDirect += ccIrradiance * BRDF_GGX_Clearcoat( directLight.direction, geometryViewDir, geometryClearcoatNormal, material );
	#endif
	#ifdef USE_SHEEN
 
 		sheenSpecularDirect += irradiance * BRDF_Sheen( directLight.direction, geometryViewDir, geometryNormal, material.sheenColor, material.sheenRoughness );
 
 		float sheenAlbedoV = IBLSheenBRDF( geometryNormal, geometryViewDir, material.sheenRoughness );
 		float sheenAlbedoL = IBLSheenBRDF( geometryNormal, directLight.direction, material.sheenRoughness );
 
 		float sheenEnergyComp = 1.0 - max3( material.sheenColor ) * max( sheenAlbedoV, sheenAlbedoL );
 
 		irradiance *= sheenEnergyComp;
 
 	#endif
	vec3 specularBRDF = BRDF_GGX( directLight.direction, geometryViewDir, geometryNormal, material );
	#ifdef USE_RETROREFLECTION
		vec3 retroViewDir = reflect( - geometryViewDir, geometryNormal );
		vec3 retroSpecularBRDF = BRDF_GGX( directLight.direction, retroViewDir, geometryNormal, material );
		specularBRDF = mix( specularBRDF, retroSpecularBRDF, saturate( material.retroreflectivity ) );
	#endif
	reflectedLight.directSpecular += irradiance * specularBRDF * material.multiScatteringCompensation;
	vec3 halfDir = normalize( directLight.direction + geometryViewDir );
	float dotVH = saturate( dot( geometryViewDir, halfDir ) );
	vec3 F = F_Schlick( material.specularColor, material.specularF90, dotVH );
	#ifdef USE_RETROREFLECTION
		vec3 retroHalfDir = normalize( directLight.direction + retroViewDir );
		float dotRetroVH = saturate( dot( retroViewDir, retroHalfDir ) );
		vec3 retroF = F_Schlick( material.specularColor, material.specularF90, dotRetroVH );
		F = mix( F, retroF, saturate( material.retroreflectivity ) );
	#endif
	#ifdef USE_DIFFUSE_ROUGHNESS
		vec3 diffuseBRDF = BRDF_EON( directLight.direction, geometryViewDir, geometryNormal, material.diffuseColor, material.diffuseRoughness ) * ( 1.0 - material.metalness );
	#else
		vec3 diffuseBRDF = BRDF_Lambert( material.diffuseContribution );
	#endif
	reflectedLight.directDiffuse += irradiance * diffuseBRDF * ( 1.0 - F );
}
void RE_IndirectDiffuse_Physical( const in vec3 irradiance, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in PhysicalMaterial material, inout ReflectedLight reflectedLight ) {
	vec3 singleScattering = vec3( 0.0 );
	vec3 multiScattering = vec3( 0.0 );
	#ifdef USE_IRIDESCENCE
		computeMultiscatteringIridescence( material.dfg, material.specularColor, material.specularF90, material.iridescence, material.iridescenceF0Dielectric, singleScattering, multiScattering );
	#else
		computeMultiscattering( material.dfg, material.specularColor, material.specularF90, singleScattering, multiScattering );
	#endif
	#ifdef USE_DIFFUSE_ROUGHNESS
		float dotNV = saturate( dot( geometryNormal, geometryViewDir ) );
		vec3 diffuseAlbedo = EON_DirectionalAlbedo( material.diffuseColor, material.diffuseRoughness, dotNV ) * ( 1.0 - material.metalness );
		vec3 diffuse = irradiance * RECIPROCAL_PI * diffuseAlbedo * ( 1.0 - singleScattering - multiScattering );
	#else
		vec3 diffuse = irradiance * BRDF_Lambert( material.diffuseContribution ) * ( 1.0 - singleScattering - multiScattering );
	#endif
	#ifdef USE_SHEEN
		float sheenAlbedo = IBLSheenBRDF( geometryNormal, geometryViewDir, material.sheenRoughness );
		sheenSpecularIndirect += irradiance * material.sheenColor * sheenAlbedo * RECIPROCAL_PI;
		float sheenEnergyComp = 1.0 - max3( material.sheenColor ) * sheenAlbedo;
		diffuse *= sheenEnergyComp;
	#endif
	reflectedLight.indirectDiffuse += diffuse;
}
void RE_IndirectSpecular_Physical( const in vec3 radiance, const in vec3 irradiance, const in vec3 clearcoatRadiance, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in PhysicalMaterial material, inout ReflectedLight reflectedLight) {
	#ifdef USE_CLEARCOAT
		clearcoatSpecularIndirect += clearcoatRadiance * EnvironmentBRDF( geometryClearcoatNormal, geometryViewDir, material.clearcoatF0, material.clearcoatF90, material.clearcoatRoughness );
	#endif
	#ifdef USE_SHEEN
		sheenSpecularIndirect += irradiance * material.sheenColor * IBLSheenBRDF( geometryNormal, geometryViewDir, material.sheenRoughness ) * RECIPROCAL_PI;
 	#endif
	vec3 singleScatteringDielectric = vec3( 0.0 );
	vec3 multiScatteringDielectric = vec3( 0.0 );
	vec3 singleScatteringMetallic = vec3( 0.0 );
	vec3 multiScatteringMetallic = vec3( 0.0 );
	#ifdef USE_IRIDESCENCE
		computeMultiscatteringIridescence( material.dfg, material.specularColor, material.specularF90, material.iridescence, material.iridescenceF0Dielectric, singleScatteringDielectric, multiScatteringDielectric );
		computeMultiscatteringIridescence( material.dfg, material.diffuseColor, material.specularF90, material.iridescence, material.iridescenceF0Metallic, singleScatteringMetallic, multiScatteringMetallic );
	#else
		computeMultiscattering( material.dfg, material.specularColor, material.specularF90, singleScatteringDielectric, multiScatteringDielectric );
		computeMultiscattering( material.dfg, material.diffuseColor, material.specularF90, singleScatteringMetallic, multiScatteringMetallic );
	#endif
	vec3 singleScattering = mix( singleScatteringDielectric, singleScatteringMetallic, material.metalness );
	vec3 multiScattering = mix( multiScatteringDielectric, multiScatteringMetallic, material.metalness );
	vec3 totalScatteringDielectric = singleScatteringDielectric + multiScatteringDielectric;
	#ifdef USE_DIFFUSE_ROUGHNESS
		float dotNV = saturate( dot( geometryNormal, geometryViewDir ) );
		vec3 diffuse = EON_DirectionalAlbedo( material.diffuseColor, material.diffuseRoughness, dotNV ) * ( 1.0 - material.metalness ) * ( 1.0 - totalScatteringDielectric );
	#else
		vec3 diffuse = material.diffuseContribution * ( 1.0 - totalScatteringDielectric );
	#endif
	vec3 cosineWeightedIrradiance = irradiance * RECIPROCAL_PI;
	vec3 indirectSpecular = radiance * singleScattering;
	indirectSpecular += multiScattering * cosineWeightedIrradiance;
	vec3 indirectDiffuse = diffuse * cosineWeightedIrradiance;
	#ifdef USE_SHEEN
		float sheenAlbedo = IBLSheenBRDF( geometryNormal, geometryViewDir, material.sheenRoughness );
		float sheenEnergyComp = 1.0 - max3( material.sheenColor ) * sheenAlbedo;
		indirectSpecular *= sheenEnergyComp;
		indirectDiffuse *= sheenEnergyComp;
	#endif
	reflectedLight.indirectSpecular += indirectSpecular;
	reflectedLight.indirectDiffuse += indirectDiffuse;
}
#define RE_Direct				RE_Direct_Physical
#define RE_Direct_RectArea		RE_Direct_RectArea_Physical
#define RE_IndirectDiffuse		RE_IndirectDiffuse_Physical
#define RE_IndirectSpecular		RE_IndirectSpecular_Physical
float computeSpecularOcclusion( const in float dotNV, const in float ambientOcclusion, const in float roughness ) {
	return saturate( pow( dotNV + ambientOcclusion, exp2( - 16.0 * roughness - 1.0 ) ) - 1.0 + ambientOcclusion );
}`,Q1=`
vec3 geometryPosition = - vViewPosition;
vec3 geometryNormal = normal;
vec3 geometryViewDir = ( isOrthographic ) ? vec3( 0, 0, 1 ) : normalize( vViewPosition );
vec3 geometryClearcoatNormal = vec3( 0.0 );
#ifdef USE_CLEARCOAT
	geometryClearcoatNormal = clearcoatNormal;
#endif
#ifdef USE_IRIDESCENCE
	float dotNVi = saturate( dot( normal, geometryViewDir ) );
	if ( material.iridescenceThickness == 0.0 ) {
		material.iridescence = 0.0;
	} else {
		material.iridescence = saturate( material.iridescence );
	}
	if ( material.iridescence > 0.0 ) {
		vec3 iridescenceFresnelDielectric = evalIridescence( 1.0, material.iridescenceIOR, dotNVi, material.iridescenceThickness, material.specularColor );
		vec3 iridescenceFresnelMetallic = evalIridescence( 1.0, material.iridescenceIOR, dotNVi, material.iridescenceThickness, material.diffuseColor );
		material.iridescenceFresnel = mix( iridescenceFresnelDielectric, iridescenceFresnelMetallic, material.metalness );
		material.iridescenceF0Dielectric = Schlick_to_F0( iridescenceFresnelDielectric, 1.0, dotNVi );
		material.iridescenceF0Metallic = Schlick_to_F0( iridescenceFresnelMetallic, 1.0, dotNVi );
	}
#endif
#ifdef STANDARD
	float dotNVms = saturate( dot( geometryNormal, geometryViewDir ) );
	material.dfg = texture2D( dfgLUT, vec2( material.roughness, dotNVms ) ).rg;
	#if ( NUM_SUN_LIGHTS > 0 || NUM_DIR_LIGHTS > 0 || NUM_POINT_LIGHTS > 0 || NUM_SPOT_LIGHTS > 0 )
		float EssMs = material.dfg.x + material.dfg.y;
		material.multiScatteringCompensation = 1.0 + material.specularColorBlended * ( 1.0 / EssMs - 1.0 );
	#endif
#endif
IncidentLight directLight;
#if ( NUM_POINT_LIGHTS > 0 ) && defined( RE_Direct )
	PointLight pointLight;
	#if defined( USE_SHADOWMAP ) && NUM_POINT_LIGHT_SHADOWS > 0
	PointLightShadow pointLightShadow;
	#endif
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_POINT_LIGHTS; i ++ ) {
		pointLight = pointLights[ i ];
		getPointLightInfo( pointLight, geometryPosition, directLight );
		#if defined( USE_SHADOWMAP ) && ( UNROLLED_LOOP_INDEX < NUM_POINT_LIGHT_SHADOWS ) && ( defined( SHADOWMAP_TYPE_PCF ) || defined( SHADOWMAP_TYPE_BASIC ) )
		pointLightShadow = pointLightShadows[ i ];
		directLight.color *= ( directLight.visible && receiveShadow ) ? getPointShadow( pointShadowMap[ i ], pointLightShadow.shadowMapSize, pointLightShadow.shadowIntensity, pointLightShadow.shadowBias, pointLightShadow.shadowRadius, vPointShadowCoord[ i ], pointLightShadow.shadowCameraNear, pointLightShadow.shadowCameraFar ) : 1.0;
		#endif
		RE_Direct( directLight, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
	}
	#pragma unroll_loop_end
#endif
#if ( NUM_SPOT_LIGHTS > 0 ) && defined( RE_Direct )
	SpotLight spotLight;
	vec4 spotColor;
	vec3 spotLightCoord;
	bool inSpotLightMap;
	#if defined( USE_SHADOWMAP ) && NUM_SPOT_LIGHT_SHADOWS > 0
	SpotLightShadow spotLightShadow;
	#endif
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_SPOT_LIGHTS; i ++ ) {
		spotLight = spotLights[ i ];
		getSpotLightInfo( spotLight, geometryPosition, directLight );
		#if ( UNROLLED_LOOP_INDEX < NUM_SPOT_LIGHT_SHADOWS_WITH_MAPS )
		#define SPOT_LIGHT_MAP_INDEX UNROLLED_LOOP_INDEX
		#elif ( UNROLLED_LOOP_INDEX < NUM_SPOT_LIGHT_SHADOWS )
		#define SPOT_LIGHT_MAP_INDEX NUM_SPOT_LIGHT_MAPS
		#else
		#define SPOT_LIGHT_MAP_INDEX ( UNROLLED_LOOP_INDEX - NUM_SPOT_LIGHT_SHADOWS + NUM_SPOT_LIGHT_SHADOWS_WITH_MAPS )
		#endif
		#if ( SPOT_LIGHT_MAP_INDEX < NUM_SPOT_LIGHT_MAPS )
			spotLightCoord = vSpotLightCoord[ i ].xyz / vSpotLightCoord[ i ].w;
			inSpotLightMap = all( lessThan( abs( spotLightCoord * 2. - 1. ), vec3( 1.0 ) ) );
			spotColor = texture2D( spotLightMap[ SPOT_LIGHT_MAP_INDEX ], spotLightCoord.xy );
			directLight.color = inSpotLightMap ? directLight.color * spotColor.rgb : directLight.color;
		#endif
		#undef SPOT_LIGHT_MAP_INDEX
		#if defined( USE_SHADOWMAP ) && ( UNROLLED_LOOP_INDEX < NUM_SPOT_LIGHT_SHADOWS )
		spotLightShadow = spotLightShadows[ i ];
		directLight.color *= ( directLight.visible && receiveShadow ) ? getShadow( spotShadowMap[ i ], spotLightShadow.shadowMapSize, spotLightShadow.shadowIntensity, spotLightShadow.shadowBias, spotLightShadow.shadowRadius, vSpotLightCoord[ i ] ) : 1.0;
		#endif
		RE_Direct( directLight, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
	}
	#pragma unroll_loop_end
#endif
#if ( NUM_SUN_LIGHTS > 0 ) && defined( RE_Direct )
	SunLight sunLight;
	#if defined( USE_SHADOWMAP ) && NUM_SUN_LIGHT_SHADOWS > 0
	SunLightShadow sunLightShadow;
	#endif
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_SUN_LIGHTS; i ++ ) {
		sunLight = sunLights[ i ];
		getSunLightInfo( sunLight, directLight );
		#if defined( USE_SHADOWMAP ) && ( UNROLLED_LOOP_INDEX < NUM_SUN_LIGHT_SHADOWS )
		sunLightShadow = sunLightShadows[ i ];
		directLight.color *= ( directLight.visible && receiveShadow ) ? getSunShadow( sunShadowMap[ i ], sunLightShadow, UNROLLED_LOOP_INDEX ) : 1.0;
		#endif
		RE_Direct( directLight, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
	}
	#pragma unroll_loop_end
#endif
#if ( NUM_DIR_LIGHTS > 0 ) && defined( RE_Direct )
	DirectionalLight directionalLight;
	#if defined( USE_SHADOWMAP ) && NUM_DIR_LIGHT_SHADOWS > 0
	DirectionalLightShadow directionalLightShadow;
	#endif
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_DIR_LIGHTS; i ++ ) {
		directionalLight = directionalLights[ i ];
		getDirectionalLightInfo( directionalLight, directLight );
		#if defined( USE_SHADOWMAP ) && ( UNROLLED_LOOP_INDEX < NUM_DIR_LIGHT_SHADOWS )
		directionalLightShadow = directionalLightShadows[ i ];
		directLight.color *= ( directLight.visible && receiveShadow ) ? getShadow( directionalShadowMap[ i ], directionalLightShadow.shadowMapSize, directionalLightShadow.shadowIntensity, directionalLightShadow.shadowBias, directionalLightShadow.shadowRadius, vDirectionalShadowCoord[ i ] ) : 1.0;
		#endif
		RE_Direct( directLight, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
	}
	#pragma unroll_loop_end
#endif
#if ( NUM_RECT_AREA_LIGHTS > 0 ) && defined( RE_Direct_RectArea )
	RectAreaLight rectAreaLight;
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_RECT_AREA_LIGHTS; i ++ ) {
		rectAreaLight = rectAreaLights[ i ];
		RE_Direct_RectArea( rectAreaLight, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
	}
	#pragma unroll_loop_end
#endif
#if defined( RE_IndirectDiffuse )
	vec3 iblIrradiance = vec3( 0.0 );
	vec3 irradiance = getAmbientLightIrradiance( ambientLightColor );
	#if defined( USE_LIGHT_PROBES )
		irradiance += getLightProbeIrradiance( lightProbe, geometryNormal );
	#endif
	#if ( NUM_HEMI_LIGHTS > 0 )
		#pragma unroll_loop_start
		for ( int i = 0; i < NUM_HEMI_LIGHTS; i ++ ) {
			irradiance += getHemisphereLightIrradiance( hemisphereLights[ i ], geometryNormal );
		}
		#pragma unroll_loop_end
	#endif
	#if NUM_LIGHT_PROBE_GRIDS > 0
		vec3 probeWorldPos = ( ( vec4( geometryPosition, 1.0 ) - viewMatrix[ 3 ] ) * viewMatrix ).xyz;
		vec3 probeWorldNormal = transformNormalByInverseViewMatrix( geometryNormal, viewMatrix );
		int probeGrid = - 1;
		#pragma unroll_loop_start
		for ( int i = 0; i < NUM_LIGHT_PROBE_GRIDS; i ++ ) {
			if ( isInsideLightProbeGrid( probeWorldPos, probeWorldNormal, probesMin[ i ], probesMax[ i ], probesResolution[ i ] ) ) probeGrid = UNROLLED_LOOP_INDEX;
		}
		#pragma unroll_loop_end
		#pragma unroll_loop_start
		for ( int i = 0; i < NUM_LIGHT_PROBE_GRIDS; i ++ ) {
			if ( probeGrid == UNROLLED_LOOP_INDEX ) irradiance += getLightProbeGridIrradiance( probesSH[ i ], probesMin[ i ], probesMax[ i ], probesResolution[ i ], probeWorldPos, probeWorldNormal );
		}
		#pragma unroll_loop_end
	#endif
#endif
#if defined( RE_IndirectSpecular )
	vec3 radiance = vec3( 0.0 );
	vec3 clearcoatRadiance = vec3( 0.0 );
#endif`,eR=`#if defined( RE_IndirectDiffuse )
	#ifdef USE_LIGHTMAP
		vec4 lightMapTexel = texture2D( lightMap, vLightMapUv );
		vec3 lightMapIrradiance = lightMapTexel.rgb * lightMapIntensity;
		irradiance += lightMapIrradiance;
	#endif
	#if defined( USE_ENVMAP ) && defined( ENVMAP_TYPE_PMREM )
		#if defined( STANDARD ) || defined( LAMBERT ) || defined( PHONG )
			iblIrradiance += getIBLIrradiance( geometryNormal );
		#endif
	#endif
#endif
#if defined( USE_ENVMAP ) && defined( RE_IndirectSpecular )
	#ifdef USE_ANISOTROPY
		vec3 iblRadiance = getIBLAnisotropyRadiance( geometryViewDir, geometryNormal, material.roughness, material.anisotropyB, material.anisotropy );
	#else
		vec3 iblRadiance = getIBLRadiance( geometryViewDir, geometryNormal, material.roughness );
	#endif
	#ifdef USE_RETROREFLECTION
		#ifdef USE_ANISOTROPY
			vec3 retroIBLRadiance = getIBLAnisotropyRetroRadiance( geometryViewDir, geometryNormal, material.roughness, material.anisotropyB, material.anisotropy );
		#else
			vec3 retroIBLRadiance = getIBLRetroRadiance( geometryViewDir, geometryNormal, material.roughness );
		#endif
		iblRadiance = mix( iblRadiance, retroIBLRadiance, saturate( material.retroreflectivity ) );
	#endif
	radiance += iblRadiance;
	#ifdef USE_CLEARCOAT
		clearcoatRadiance += getIBLRadiance( geometryViewDir, geometryClearcoatNormal, material.clearcoatRoughness );
	#endif
#endif`,tR=`#if defined( RE_IndirectDiffuse )
	#if defined( LAMBERT ) || defined( PHONG )
		irradiance += iblIrradiance;
	#endif
	RE_IndirectDiffuse( irradiance, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
#endif
#if defined( RE_IndirectSpecular )
	RE_IndirectSpecular( radiance, iblIrradiance, clearcoatRadiance, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
#endif`,nR=`#if NUM_LIGHT_PROBE_GRIDS > 0
uniform highp sampler3D probesSH[ NUM_LIGHT_PROBE_GRIDS ];
uniform vec3 probesMin[ NUM_LIGHT_PROBE_GRIDS ];
uniform vec3 probesMax[ NUM_LIGHT_PROBE_GRIDS ];
uniform vec3 probesResolution[ NUM_LIGHT_PROBE_GRIDS ];
bool isInsideLightProbeGrid( vec3 worldPos, vec3 worldNormal, vec3 probesMin, vec3 probesMax, vec3 probesResolution ) {
	vec3 spacing = ( probesMax - probesMin ) / probesResolution;
	vec3 samplePos = worldPos + worldNormal * spacing * 0.5;
	vec3 margin = spacing * 0.01;
	return all( greaterThanEqual( samplePos, probesMin - margin ) ) && all( lessThanEqual( samplePos, probesMax + margin ) );
}
vec3 getLightProbeGridIrradiance( highp sampler3D probesSH, vec3 probesMin, vec3 probesMax, vec3 probesResolution, vec3 worldPos, vec3 worldNormal ) {
	vec3 res = probesResolution;
	vec3 gridRange = probesMax - probesMin;
	vec3 probeSpacing = gridRange / res;
	vec3 samplePos = worldPos + worldNormal * probeSpacing * 0.5;
	vec3 uvw = clamp( ( samplePos - probesMin ) / gridRange, 0.5 / res, 1.0 - 0.5 / res );
	float nz          = res.z;
	float paddedSlices = nz + 2.0;
	float atlasDepth  = 7.0 * paddedSlices;
	float uvZBase     = uvw.z * nz + 1.0;
	vec4 s0 = texture( probesSH, vec3( uvw.xy, ( uvZBase                       ) / atlasDepth ) );
	vec4 s1 = texture( probesSH, vec3( uvw.xy, ( uvZBase +       paddedSlices   ) / atlasDepth ) );
	vec4 s2 = texture( probesSH, vec3( uvw.xy, ( uvZBase + 2.0 * paddedSlices   ) / atlasDepth ) );
	vec4 s3 = texture( probesSH, vec3( uvw.xy, ( uvZBase + 3.0 * paddedSlices   ) / atlasDepth ) );
	vec4 s4 = texture( probesSH, vec3( uvw.xy, ( uvZBase + 4.0 * paddedSlices   ) / atlasDepth ) );
	vec4 s5 = texture( probesSH, vec3( uvw.xy, ( uvZBase + 5.0 * paddedSlices   ) / atlasDepth ) );
	vec4 s6 = texture( probesSH, vec3( uvw.xy, ( uvZBase + 6.0 * paddedSlices   ) / atlasDepth ) );
	vec3 c0 = s0.xyz;
	vec3 c1 = vec3( s0.w, s1.xy );
	vec3 c2 = vec3( s1.zw, s2.x );
	vec3 c3 = s2.yzw;
	vec3 c4 = s3.xyz;
	vec3 c5 = vec3( s3.w, s4.xy );
	vec3 c6 = vec3( s4.zw, s5.x );
	vec3 c7 = s5.yzw;
	vec3 c8 = s6.xyz;
	float x = worldNormal.x, y = worldNormal.y, z = worldNormal.z;
	vec3 result = c0 * 0.886227;
	result += c1 * 2.0 * 0.511664 * y;
	result += c2 * 2.0 * 0.511664 * z;
	result += c3 * 2.0 * 0.511664 * x;
	result += c4 * 2.0 * 0.429043 * x * y;
	result += c5 * 2.0 * 0.429043 * y * z;
	result += c6 * ( 0.743125 * z * z - 0.247708 );
	result += c7 * 2.0 * 0.429043 * x * z;
	result += c8 * 0.429043 * ( x * x - y * y );
	return max( result, vec3( 0.0 ) );
}
#endif`,iR=`#if defined( USE_LOGARITHMIC_DEPTH_BUFFER )
	gl_FragDepth = vIsPerspective == 0.0 ? gl_FragCoord.z : log2( vFragDepth ) * logDepthBufFC * 0.5;
#endif`,rR=`#if defined( USE_LOGARITHMIC_DEPTH_BUFFER )
	uniform float logDepthBufFC;
	varying float vFragDepth;
	varying float vIsPerspective;
#endif`,sR=`#ifdef USE_LOGARITHMIC_DEPTH_BUFFER
	varying float vFragDepth;
	varying float vIsPerspective;
#endif`,oR=`#ifdef USE_LOGARITHMIC_DEPTH_BUFFER
	vFragDepth = 1.0 + gl_Position.w;
	vIsPerspective = float( isPerspectiveMatrix( projectionMatrix ) );
#endif`,aR=`#ifdef USE_MAP
	vec4 sampledDiffuseColor = texture2D( map, vMapUv );
	#ifdef DECODE_VIDEO_TEXTURE
		sampledDiffuseColor = sRGBTransferEOTF( sampledDiffuseColor );
	#endif
	diffuseColor *= sampledDiffuseColor;
#endif`,lR=`#ifdef USE_MAP
	uniform sampler2D map;
#endif`,cR=`#if defined( USE_MAP ) || defined( USE_ALPHAMAP )
	#if defined( USE_POINTS_UV )
		vec2 uv = vUv;
	#else
		vec2 uv = ( uvTransform * vec3( gl_PointCoord.x, 1.0 - gl_PointCoord.y, 1 ) ).xy;
	#endif
#endif
#ifdef USE_MAP
	diffuseColor *= texture2D( map, uv );
#endif
#ifdef USE_ALPHAMAP
	diffuseColor.a *= texture2D( alphaMap, uv ).g;
#endif`,uR=`#if defined( USE_POINTS_UV )
	varying vec2 vUv;
#else
	#if defined( USE_MAP ) || defined( USE_ALPHAMAP )
		uniform mat3 uvTransform;
	#endif
#endif
#ifdef USE_MAP
	uniform sampler2D map;
#endif
#ifdef USE_ALPHAMAP
	uniform sampler2D alphaMap;
#endif`,hR=`float metalnessFactor = metalness;
#ifdef USE_METALNESSMAP
	vec4 texelMetalness = texture2D( metalnessMap, vMetalnessMapUv );
	metalnessFactor *= texelMetalness.b;
#endif`,fR=`#ifdef USE_METALNESSMAP
	uniform sampler2D metalnessMap;
#endif`,dR=`#ifdef USE_INSTANCING_MORPH
	float morphTargetInfluences[ MORPHTARGETS_COUNT ];
	float morphTargetBaseInfluence = texelFetch( morphTexture, ivec2( 0, gl_InstanceID ), 0 ).r;
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		morphTargetInfluences[i] =  texelFetch( morphTexture, ivec2( i + 1, gl_InstanceID ), 0 ).r;
	}
#endif`,pR=`#if defined( USE_MORPHCOLORS )
	#if defined( USE_COLOR_ALPHA )
		vColor *= morphTargetBaseInfluence;
	#elif defined( USE_COLOR )
		vColor.rgb *= morphTargetBaseInfluence;
	#endif
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		#if defined( USE_COLOR_ALPHA )
			if ( morphTargetInfluences[ i ] != 0.0 ) vColor += getMorph( gl_VertexID, i, 2 ) * morphTargetInfluences[ i ];
		#elif defined( USE_COLOR )
			if ( morphTargetInfluences[ i ] != 0.0 ) vColor.rgb += getMorph( gl_VertexID, i, 2 ).rgb * morphTargetInfluences[ i ];
		#endif
	}
#endif`,mR=`#ifdef USE_MORPHNORMALS
	objectNormal *= morphTargetBaseInfluence;
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		if ( morphTargetInfluences[ i ] != 0.0 ) objectNormal += getMorph( gl_VertexID, i, 1 ).xyz * morphTargetInfluences[ i ];
	}
#endif`,gR=`#ifdef USE_MORPHTARGETS
	#ifndef USE_INSTANCING_MORPH
		uniform float morphTargetBaseInfluence;
		uniform float morphTargetInfluences[ MORPHTARGETS_COUNT ];
	#endif
	uniform sampler2DArray morphTargetsTexture;
	uniform ivec2 morphTargetsTextureSize;
	vec4 getMorph( const in int vertexIndex, const in int morphTargetIndex, const in int offset ) {
		int texelIndex = vertexIndex * MORPHTARGETS_TEXTURE_STRIDE + offset;
		int y = texelIndex / morphTargetsTextureSize.x;
		int x = texelIndex - y * morphTargetsTextureSize.x;
		ivec3 morphUV = ivec3( x, y, morphTargetIndex );
		return texelFetch( morphTargetsTexture, morphUV, 0 );
	}
#endif`,_R=`#ifdef USE_MORPHTARGETS
	transformed *= morphTargetBaseInfluence;
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		if ( morphTargetInfluences[ i ] != 0.0 ) transformed += getMorph( gl_VertexID, i, 0 ).xyz * morphTargetInfluences[ i ];
	}
#endif`,yR=`float faceDirection = gl_FrontFacing ? 1.0 : - 1.0;
#ifdef FLAT_SHADED
	vec3 fdx = dFdx( vViewPosition );
	vec3 fdy = dFdy( vViewPosition );
	vec3 normal = normalize( cross( fdx, fdy ) );
#else
	vec3 normal = normalize( vNormal );
	#ifdef DOUBLE_SIDED
		normal *= faceDirection;
	#endif
#endif
#if defined( USE_NORMALMAP_TANGENTSPACE ) || defined( USE_CLEARCOAT_NORMALMAP ) || defined( USE_ANISOTROPY )
	#ifdef USE_TANGENT
		mat3 tbn = mat3( normalize( vTangent ), normalize( vBitangent ), normal );
	#else
		mat3 tbn = getTangentFrame( - vViewPosition, normal,
		#if defined( USE_NORMALMAP )
			vNormalMapUv
		#elif defined( USE_CLEARCOAT_NORMALMAP )
			vClearcoatNormalMapUv
		#else
			vUv
		#endif
		);
	#endif
	#ifdef DOUBLE_SIDED
		tbn[0] *= faceDirection;
		tbn[1] *= faceDirection;
	#endif
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	#ifdef USE_TANGENT
		mat3 tbn2 = mat3( normalize( vTangent ), normalize( vBitangent ), normal );
	#else
		mat3 tbn2 = getTangentFrame( - vViewPosition, normal, vClearcoatNormalMapUv );
	#endif
	#ifdef DOUBLE_SIDED
		tbn2[0] *= faceDirection;
		tbn2[1] *= faceDirection;
	#endif
#endif
vec3 nonPerturbedNormal = normal;`,xR=`#ifdef USE_NORMALMAP_OBJECTSPACE
	normal = texture2D( normalMap, vNormalMapUv ).xyz * 2.0 - 1.0;
	#ifdef FLIP_SIDED
		normal = - normal;
	#endif
	#ifdef DOUBLE_SIDED
		normal = normal * faceDirection;
	#endif
	normal = normalize( normalMatrix * normal );
#elif defined( USE_NORMALMAP_TANGENTSPACE )
	vec3 mapN = texture2D( normalMap, vNormalMapUv ).xyz * 2.0 - 1.0;
	#if defined( USE_PACKED_NORMALMAP )
		mapN = vec3( mapN.xy, sqrt( saturate( 1.0 - dot( mapN.xy, mapN.xy ) ) ) );
	#endif
	mapN.xy *= normalScale;
	normal = normalize( tbn * mapN );
#elif defined( USE_BUMPMAP )
	normal = perturbNormalArb( - vViewPosition, normal, dHdxy_fwd(), faceDirection );
#endif`,bR=`#ifndef FLAT_SHADED
	varying vec3 vNormal;
	#ifdef USE_TANGENT
		varying vec3 vTangent;
		varying vec3 vBitangent;
	#endif
#endif`,vR=`#ifndef FLAT_SHADED
	varying vec3 vNormal;
	#ifdef USE_TANGENT
		varying vec3 vTangent;
		varying vec3 vBitangent;
	#endif
#endif`,SR=`#ifndef FLAT_SHADED
	vNormal = normalize( transformedNormal );
	#ifdef USE_TANGENT
		vTangent = normalize( transformedTangent );
		vBitangent = normalize( cross( vNormal, vTangent ) * tangent.w );
		#ifdef FLIP_SIDED
			vBitangent = - vBitangent;
		#endif
	#endif
#endif`,ER=`#ifdef USE_NORMALMAP
	uniform sampler2D normalMap;
	uniform vec2 normalScale;
#endif
#ifdef USE_NORMALMAP_OBJECTSPACE
	uniform mat3 normalMatrix;
#endif
#if ! defined ( USE_TANGENT ) && ( defined ( USE_NORMALMAP_TANGENTSPACE ) || defined ( USE_CLEARCOAT_NORMALMAP ) || defined( USE_ANISOTROPY ) )
	mat3 getTangentFrame( vec3 eye_pos, vec3 surf_norm, vec2 uv ) {
		vec3 q0 = dFdx( eye_pos.xyz );
		vec3 q1 = dFdy( eye_pos.xyz );
		vec2 st0 = dFdx( uv.st );
		vec2 st1 = dFdy( uv.st );
		vec3 N = surf_norm;
		vec3 q1perp = cross( q1, N );
		vec3 q0perp = cross( N, q0 );
		vec3 T = q1perp * st0.x + q0perp * st1.x;
		vec3 B = q1perp * st0.y + q0perp * st1.y;
		float det = max( dot( T, T ), dot( B, B ) );
		float scale = ( det == 0.0 ) ? 0.0 : inversesqrt( det );
		return mat3( T * scale, B * scale, N );
	}
#endif`,MR=`#ifdef USE_CLEARCOAT
	vec3 clearcoatNormal = nonPerturbedNormal;
#endif`,wR=`#ifdef USE_CLEARCOAT_NORMALMAP
	vec3 clearcoatMapN = texture2D( clearcoatNormalMap, vClearcoatNormalMapUv ).xyz * 2.0 - 1.0;
	clearcoatMapN.xy *= clearcoatNormalScale;
	clearcoatNormal = normalize( tbn2 * clearcoatMapN );
#endif`,TR=`#ifdef USE_CLEARCOATMAP
	uniform sampler2D clearcoatMap;
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	uniform sampler2D clearcoatNormalMap;
	uniform vec2 clearcoatNormalScale;
#endif
#ifdef USE_CLEARCOAT_ROUGHNESSMAP
	uniform sampler2D clearcoatRoughnessMap;
#endif`,AR=`#ifdef USE_IRIDESCENCEMAP
	uniform sampler2D iridescenceMap;
#endif
#ifdef USE_IRIDESCENCE_THICKNESSMAP
	uniform sampler2D iridescenceThicknessMap;
#endif`,RR=`#ifdef OPAQUE
diffuseColor.a = 1.0;
#endif
#ifdef USE_TRANSMISSION
diffuseColor.a *= material.transmissionAlpha;
#endif
gl_FragColor = vec4( outgoingLight, diffuseColor.a );`,IR=`vec3 packNormalToRGB( const in vec3 normal ) {
	return normalize( normal ) * 0.5 + 0.5;
}
vec3 unpackRGBToNormal( const in vec3 rgb ) {
	return 2.0 * rgb.xyz - 1.0;
}
const float PackUpscale = 256. / 255.;const float UnpackDownscale = 255. / 256.;const float ShiftRight8 = 1. / 256.;
const float Inv255 = 1. / 255.;
const vec4 PackFactors = vec4( 1.0, 256.0, 256.0 * 256.0, 256.0 * 256.0 * 256.0 );
const vec2 UnpackFactors2 = vec2( UnpackDownscale, 1.0 / PackFactors.g );
const vec3 UnpackFactors3 = vec3( UnpackDownscale / PackFactors.rg, 1.0 / PackFactors.b );
const vec4 UnpackFactors4 = vec4( UnpackDownscale / PackFactors.rgb, 1.0 / PackFactors.a );
vec4 packDepthToRGBA( const in float v ) {
	if( v <= 0.0 )
		return vec4( 0., 0., 0., 0. );
	if( v >= 1.0 )
		return vec4( 1., 1., 1., 1. );
	float vuf;
	float af = modf( v * PackFactors.a, vuf );
	float bf = modf( vuf * ShiftRight8, vuf );
	float gf = modf( vuf * ShiftRight8, vuf );
	return vec4( vuf * Inv255, gf * PackUpscale, bf * PackUpscale, af );
}
vec3 packDepthToRGB( const in float v ) {
	if( v <= 0.0 )
		return vec3( 0., 0., 0. );
	if( v >= 1.0 )
		return vec3( 1., 1., 1. );
	float vuf;
	float bf = modf( v * PackFactors.b, vuf );
	float gf = modf( vuf * ShiftRight8, vuf );
	return vec3( vuf * Inv255, gf * PackUpscale, bf );
}
vec2 packDepthToRG( const in float v ) {
	if( v <= 0.0 )
		return vec2( 0., 0. );
	if( v >= 1.0 )
		return vec2( 1., 1. );
	float vuf;
	float gf = modf( v * 256., vuf );
	return vec2( vuf * Inv255, gf );
}
float unpackRGBAToDepth( const in vec4 v ) {
	return dot( v, UnpackFactors4 );
}
float unpackRGBToDepth( const in vec3 v ) {
	return dot( v, UnpackFactors3 );
}
float unpackRGToDepth( const in vec2 v ) {
	return v.r * UnpackFactors2.r + v.g * UnpackFactors2.g;
}
vec4 pack2HalfToRGBA( const in vec2 v ) {
	vec4 r = vec4( v.x, fract( v.x * 255.0 ), v.y, fract( v.y * 255.0 ) );
	return vec4( r.x - r.y / 255.0, r.y, r.z - r.w / 255.0, r.w );
}
vec2 unpackRGBATo2Half( const in vec4 v ) {
	return vec2( v.x + ( v.y / 255.0 ), v.z + ( v.w / 255.0 ) );
}
float viewZToOrthographicDepth( const in float viewZ, const in float near, const in float far ) {
	return ( viewZ + near ) / ( near - far );
}
float orthographicDepthToViewZ( const in float depth, const in float near, const in float far ) {
	#ifdef USE_REVERSED_DEPTH_BUFFER
	
		return depth * ( far - near ) - far;
	#else
		return depth * ( near - far ) - near;
	#endif
}
float viewZToPerspectiveDepth( const in float viewZ, const in float near, const in float far ) {
	return ( ( near + viewZ ) * far ) / ( ( far - near ) * viewZ );
}
float perspectiveDepthToViewZ( const in float depth, const in float near, const in float far ) {
	
	#ifdef USE_REVERSED_DEPTH_BUFFER
		return ( near * far ) / ( ( near - far ) * depth - near );
	#else
		return ( near * far ) / ( ( far - near ) * depth - far );
	#endif
}`,CR=`#ifdef PREMULTIPLIED_ALPHA
	gl_FragColor.rgb *= gl_FragColor.a;
#endif`,NR=`vec4 mvPosition = vec4( transformed, 1.0 );
#ifdef USE_BATCHING
	mvPosition = batchingMatrix * mvPosition;
#endif
#ifdef USE_INSTANCING
	mvPosition = instanceMatrix * mvPosition;
#endif
mvPosition = modelViewMatrix * mvPosition;
gl_Position = projectionMatrix * mvPosition;`,PR=`#ifdef DITHERING
	gl_FragColor.rgb = dithering( gl_FragColor.rgb );
#endif`,LR=`#ifdef DITHERING
	vec3 dithering( vec3 color ) {
		float grid_position = rand( gl_FragCoord.xy );
		vec3 dither_shift_RGB = vec3( 0.25 / 255.0, -0.25 / 255.0, 0.25 / 255.0 );
		dither_shift_RGB = mix( 2.0 * dither_shift_RGB, -2.0 * dither_shift_RGB, grid_position );
		return color + dither_shift_RGB;
	}
#endif`,DR=`float roughnessFactor = roughness;
#ifdef USE_ROUGHNESSMAP
	vec4 texelRoughness = texture2D( roughnessMap, vRoughnessMapUv );
	roughnessFactor *= texelRoughness.g;
#endif`,FR=`#ifdef USE_ROUGHNESSMAP
	uniform sampler2D roughnessMap;
#endif`,UR=`#if NUM_SPOT_LIGHT_COORDS > 0
	varying vec4 vSpotLightCoord[ NUM_SPOT_LIGHT_COORDS ];
#endif
#if NUM_SPOT_LIGHT_MAPS > 0
	uniform sampler2D spotLightMap[ NUM_SPOT_LIGHT_MAPS ];
#endif
#ifdef USE_SHADOWMAP
	#if NUM_SUN_LIGHT_SHADOWS > 0
		#define SUN_LIGHT_CASCADES 2
		#if defined( SHADOWMAP_TYPE_PCF )
			uniform sampler2DShadow sunShadowMap[ NUM_SUN_LIGHT_SHADOWS ];
		#else
			uniform sampler2D sunShadowMap[ NUM_SUN_LIGHT_SHADOWS ];
		#endif
		uniform mat4 sunShadowMatrix[ NUM_SUN_LIGHT_SHADOWS * SUN_LIGHT_CASCADES ];
		uniform vec4 sunShadowCascade[ NUM_SUN_LIGHT_SHADOWS * SUN_LIGHT_CASCADES ];
		varying vec4 vSunShadowWorldPosition;
		varying vec3 vSunShadowWorldNormal;
		struct SunLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
		};
		uniform SunLightShadow sunLightShadows[ NUM_SUN_LIGHT_SHADOWS ];
	#endif
	#if NUM_DIR_LIGHT_SHADOWS > 0
		#if defined( SHADOWMAP_TYPE_PCF )
			uniform sampler2DShadow directionalShadowMap[ NUM_DIR_LIGHT_SHADOWS ];
		#else
			uniform sampler2D directionalShadowMap[ NUM_DIR_LIGHT_SHADOWS ];
		#endif
		varying vec4 vDirectionalShadowCoord[ NUM_DIR_LIGHT_SHADOWS ];
		struct DirectionalLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
		};
		uniform DirectionalLightShadow directionalLightShadows[ NUM_DIR_LIGHT_SHADOWS ];
	#endif
	#if NUM_SPOT_LIGHT_SHADOWS > 0
		#if defined( SHADOWMAP_TYPE_PCF )
			uniform sampler2DShadow spotShadowMap[ NUM_SPOT_LIGHT_SHADOWS ];
		#else
			uniform sampler2D spotShadowMap[ NUM_SPOT_LIGHT_SHADOWS ];
		#endif
		struct SpotLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
		};
		uniform SpotLightShadow spotLightShadows[ NUM_SPOT_LIGHT_SHADOWS ];
	#endif
	#if NUM_POINT_LIGHT_SHADOWS > 0
		#if defined( SHADOWMAP_TYPE_PCF )
			uniform samplerCubeShadow pointShadowMap[ NUM_POINT_LIGHT_SHADOWS ];
		#elif defined( SHADOWMAP_TYPE_BASIC )
			uniform samplerCube pointShadowMap[ NUM_POINT_LIGHT_SHADOWS ];
		#endif
		varying vec4 vPointShadowCoord[ NUM_POINT_LIGHT_SHADOWS ];
		struct PointLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
			float shadowCameraNear;
			float shadowCameraFar;
		};
		uniform PointLightShadow pointLightShadows[ NUM_POINT_LIGHT_SHADOWS ];
	#endif
	#if defined( SHADOWMAP_TYPE_PCF )
		float interleavedGradientNoise( vec2 position ) {
			return fract( 52.9829189 * fract( dot( position, vec2( 0.06711056, 0.00583715 ) ) ) );
		}
		vec2 vogelDiskSample( int sampleIndex, int samplesCount, float phi ) {
			const float goldenAngle = 2.399963229728653;
			float r = sqrt( ( float( sampleIndex ) + 0.5 ) / float( samplesCount ) );
			float theta = float( sampleIndex ) * goldenAngle + phi;
			return vec2( cos( theta ), sin( theta ) ) * r;
		}
	#endif
	#if defined( SHADOWMAP_TYPE_PCF )
		float getShadow( sampler2DShadow shadowMap, vec2 shadowMapSize, float shadowIntensity, float shadowBias, float shadowRadius, vec4 shadowCoord ) {
			float shadow = 1.0;
			shadowCoord.xyz /= shadowCoord.w;
			#ifdef USE_REVERSED_DEPTH_BUFFER
				shadowCoord.z -= shadowBias;
			#else
				shadowCoord.z += shadowBias;
			#endif
			bool inFrustum = shadowCoord.x >= 0.0 && shadowCoord.x <= 1.0 && shadowCoord.y >= 0.0 && shadowCoord.y <= 1.0;
			bool frustumTest = inFrustum && shadowCoord.z <= 1.0;
			if ( frustumTest ) {
				vec2 texelSize = vec2( 1.0 ) / shadowMapSize;
				vec2 radius = shadowRadius * texelSize;
				float phi = interleavedGradientNoise( gl_FragCoord.xy ) * PI2;
				shadow = (
					texture( shadowMap, vec3( shadowCoord.xy + vogelDiskSample( 0, 5, phi ) * radius, shadowCoord.z ) ) +
					texture( shadowMap, vec3( shadowCoord.xy + vogelDiskSample( 1, 5, phi ) * radius, shadowCoord.z ) ) +
					texture( shadowMap, vec3( shadowCoord.xy + vogelDiskSample( 2, 5, phi ) * radius, shadowCoord.z ) ) +
					texture( shadowMap, vec3( shadowCoord.xy + vogelDiskSample( 3, 5, phi ) * radius, shadowCoord.z ) ) +
					texture( shadowMap, vec3( shadowCoord.xy + vogelDiskSample( 4, 5, phi ) * radius, shadowCoord.z ) )
				) * 0.2;
			}
			return mix( 1.0, shadow, shadowIntensity );
		}
	#elif defined( SHADOWMAP_TYPE_VSM )
		float getShadow( sampler2D shadowMap, vec2 shadowMapSize, float shadowIntensity, float shadowBias, float shadowRadius, vec4 shadowCoord ) {
			float shadow = 1.0;
			shadowCoord.xyz /= shadowCoord.w;
			#ifdef USE_REVERSED_DEPTH_BUFFER
				shadowCoord.z -= shadowBias;
			#else
				shadowCoord.z += shadowBias;
			#endif
			bool inFrustum = shadowCoord.x >= 0.0 && shadowCoord.x <= 1.0 && shadowCoord.y >= 0.0 && shadowCoord.y <= 1.0;
			bool frustumTest = inFrustum && shadowCoord.z <= 1.0;
			if ( frustumTest ) {
				vec2 distribution = texture2D( shadowMap, shadowCoord.xy ).rg;
				float mean = distribution.x;
				float variance = distribution.y * distribution.y;
				#ifdef USE_REVERSED_DEPTH_BUFFER
					float hard_shadow = step( mean, shadowCoord.z );
				#else
					float hard_shadow = step( shadowCoord.z, mean );
				#endif
				
				if ( hard_shadow == 1.0 ) {
					shadow = 1.0;
				} else {
					variance = max( variance, 0.0000001 );
					float d = shadowCoord.z - mean;
					float p_max = variance / ( variance + d * d );
					p_max = clamp( ( p_max - 0.3 ) / 0.65, 0.0, 1.0 );
					shadow = max( hard_shadow, p_max );
				}
			}
			return mix( 1.0, shadow, shadowIntensity );
		}
	#else
		float getShadow( sampler2D shadowMap, vec2 shadowMapSize, float shadowIntensity, float shadowBias, float shadowRadius, vec4 shadowCoord ) {
			float shadow = 1.0;
			shadowCoord.xyz /= shadowCoord.w;
			#ifdef USE_REVERSED_DEPTH_BUFFER
				shadowCoord.z -= shadowBias;
			#else
				shadowCoord.z += shadowBias;
			#endif
			bool inFrustum = shadowCoord.x >= 0.0 && shadowCoord.x <= 1.0 && shadowCoord.y >= 0.0 && shadowCoord.y <= 1.0;
			bool frustumTest = inFrustum && shadowCoord.z <= 1.0;
			if ( frustumTest ) {
				float depth = texture2D( shadowMap, shadowCoord.xy ).r;
				#ifdef USE_REVERSED_DEPTH_BUFFER
					shadow = step( depth, shadowCoord.z );
				#else
					shadow = step( shadowCoord.z, depth );
				#endif
			}
			return mix( 1.0, shadow, shadowIntensity );
		}
	#endif
	#if NUM_SUN_LIGHT_SHADOWS > 0
		float getSunShadow(
			#if defined( SHADOWMAP_TYPE_PCF )
				sampler2DShadow shadowMap,
			#else
				sampler2D shadowMap,
			#endif
			SunLightShadow sunLightShadow,
			int shadowIndex
		) {
			vec4 shadowWorldPosition = vec4( vSunShadowWorldPosition.xyz + vSunShadowWorldNormal * sunLightShadow.shadowNormalBias, 1.0 );
			float viewDepth = vSunShadowWorldPosition.w;
			int cascadeOffset = shadowIndex * SUN_LIGHT_CASCADES;
			float shadow = 1.0;
			for ( int i = SUN_LIGHT_CASCADES - 1; i >= 0; i -- ) {
				vec4 cascade = sunShadowCascade[ cascadeOffset + i ];
				if ( viewDepth >= cascade.x && viewDepth < cascade.y ) {
					float cascadeShadow = getShadow(
						shadowMap,
						sunLightShadow.shadowMapSize,
						sunLightShadow.shadowIntensity,
						sunLightShadow.shadowBias,
						sunLightShadow.shadowRadius,
						sunShadowMatrix[ cascadeOffset + i ] * shadowWorldPosition
					);
					shadow = mix( cascadeShadow, shadow, smoothstep( cascade.z, cascade.y, viewDepth ) );
				}
			}
			return shadow;
		}
	#endif
	#if NUM_POINT_LIGHT_SHADOWS > 0
	#if defined( SHADOWMAP_TYPE_PCF )
	float getPointShadow( samplerCubeShadow shadowMap, vec2 shadowMapSize, float shadowIntensity, float shadowBias, float shadowRadius, vec4 shadowCoord, float shadowCameraNear, float shadowCameraFar ) {
		float shadow = 1.0;
		vec3 lightToPosition = shadowCoord.xyz;
		vec3 bd3D = normalize( lightToPosition );
		vec3 absVec = abs( lightToPosition );
		float viewSpaceZ = max( max( absVec.x, absVec.y ), absVec.z );
		if ( viewSpaceZ - shadowCameraFar <= 0.0 && viewSpaceZ - shadowCameraNear >= 0.0 ) {
			float lightDistance = length( lightToPosition );
			float depthRange = shadowCameraFar - shadowCameraNear;
			#ifdef USE_REVERSED_DEPTH_BUFFER
				float depthA = - shadowCameraNear / depthRange - shadowBias;
				float depthB = shadowCameraNear * shadowCameraFar / ( depthRange * lightDistance );
			#else
				float depthA = shadowCameraFar / depthRange + shadowBias;
				float depthB = - shadowCameraNear * shadowCameraFar / ( depthRange * lightDistance );
			#endif
			float texelSize = shadowRadius / shadowMapSize.x;
			vec3 absDir = abs( bd3D );
			vec3 tangent = absDir.x > absDir.z ? vec3( 0.0, 1.0, 0.0 ) : vec3( 1.0, 0.0, 0.0 );
			tangent = normalize( cross( bd3D, tangent ) );
			vec3 bitangent = cross( bd3D, tangent );
			float phi = interleavedGradientNoise( gl_FragCoord.xy ) * PI2;
			shadow = 0.0;
			for ( int i = 0; i < 5; i ++ ) {
				vec2 offset = vogelDiskSample( i, 5, phi );
				vec3 direction = bd3D + ( tangent * offset.x + bitangent * offset.y ) * texelSize;
				vec3 absDirection = abs( direction );
				float dp = depthA + depthB / max( max( absDirection.x, absDirection.y ), absDirection.z );
				shadow += texture( shadowMap, vec4( direction, dp ) );
			}
			shadow *= 0.2;
		}
		return mix( 1.0, shadow, shadowIntensity );
	}
	#elif defined( SHADOWMAP_TYPE_BASIC )
	float getPointShadow( samplerCube shadowMap, vec2 shadowMapSize, float shadowIntensity, float shadowBias, float shadowRadius, vec4 shadowCoord, float shadowCameraNear, float shadowCameraFar ) {
		float shadow = 1.0;
		vec3 lightToPosition = shadowCoord.xyz;
		vec3 absVec = abs( lightToPosition );
		float viewSpaceZ = max( max( absVec.x, absVec.y ), absVec.z );
		if ( viewSpaceZ - shadowCameraFar <= 0.0 && viewSpaceZ - shadowCameraNear >= 0.0 ) {
			float dp = ( shadowCameraFar * ( viewSpaceZ - shadowCameraNear ) ) / ( viewSpaceZ * ( shadowCameraFar - shadowCameraNear ) );
			dp += shadowBias;
			vec3 bd3D = normalize( lightToPosition );
			float depth = textureCube( shadowMap, bd3D ).r;
			#ifdef USE_REVERSED_DEPTH_BUFFER
				depth = 1.0 - depth;
			#endif
			shadow = step( dp, depth );
		}
		return mix( 1.0, shadow, shadowIntensity );
	}
	#endif
	#endif
#endif`,OR=`#if NUM_SPOT_LIGHT_COORDS > 0
	uniform mat4 spotLightMatrix[ NUM_SPOT_LIGHT_COORDS ];
	varying vec4 vSpotLightCoord[ NUM_SPOT_LIGHT_COORDS ];
#endif
#ifdef USE_SHADOWMAP
	#if NUM_SUN_LIGHT_SHADOWS > 0
		varying vec4 vSunShadowWorldPosition;
		varying vec3 vSunShadowWorldNormal;
	#endif
	#if NUM_DIR_LIGHT_SHADOWS > 0
		uniform mat4 directionalShadowMatrix[ NUM_DIR_LIGHT_SHADOWS ];
		varying vec4 vDirectionalShadowCoord[ NUM_DIR_LIGHT_SHADOWS ];
		struct DirectionalLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
		};
		uniform DirectionalLightShadow directionalLightShadows[ NUM_DIR_LIGHT_SHADOWS ];
	#endif
	#if NUM_SPOT_LIGHT_SHADOWS > 0
		struct SpotLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
		};
		uniform SpotLightShadow spotLightShadows[ NUM_SPOT_LIGHT_SHADOWS ];
	#endif
	#if NUM_POINT_LIGHT_SHADOWS > 0
		uniform mat4 pointShadowMatrix[ NUM_POINT_LIGHT_SHADOWS ];
		varying vec4 vPointShadowCoord[ NUM_POINT_LIGHT_SHADOWS ];
		struct PointLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
			float shadowCameraNear;
			float shadowCameraFar;
		};
		uniform PointLightShadow pointLightShadows[ NUM_POINT_LIGHT_SHADOWS ];
	#endif
#endif`,BR=`#if ( defined( USE_SHADOWMAP ) && ( NUM_DIR_LIGHT_SHADOWS > 0 || NUM_SUN_LIGHT_SHADOWS > 0 || NUM_POINT_LIGHT_SHADOWS > 0 ) ) || ( NUM_SPOT_LIGHT_COORDS > 0 )
	#ifdef HAS_NORMAL
		vec3 shadowWorldNormal = transformNormalByInverseViewMatrix( transformedNormal, viewMatrix );
	#else
		vec3 shadowWorldNormal = vec3( 0.0 );
	#endif
	vec4 shadowWorldPosition;
#endif
#if defined( USE_SHADOWMAP )
	#if NUM_SUN_LIGHT_SHADOWS > 0
		vSunShadowWorldPosition = vec4( worldPosition.xyz, - mvPosition.z );
		vSunShadowWorldNormal = shadowWorldNormal;
	#endif
	#if NUM_DIR_LIGHT_SHADOWS > 0
		#pragma unroll_loop_start
		for ( int i = 0; i < NUM_DIR_LIGHT_SHADOWS; i ++ ) {
			shadowWorldPosition = worldPosition + vec4( shadowWorldNormal * directionalLightShadows[ i ].shadowNormalBias, 0 );
			vDirectionalShadowCoord[ i ] = directionalShadowMatrix[ i ] * shadowWorldPosition;
		}
		#pragma unroll_loop_end
	#endif
	#if NUM_POINT_LIGHT_SHADOWS > 0
		#pragma unroll_loop_start
		for ( int i = 0; i < NUM_POINT_LIGHT_SHADOWS; i ++ ) {
			shadowWorldPosition = worldPosition + vec4( shadowWorldNormal * pointLightShadows[ i ].shadowNormalBias, 0 );
			vPointShadowCoord[ i ] = pointShadowMatrix[ i ] * shadowWorldPosition;
		}
		#pragma unroll_loop_end
	#endif
#endif
#if NUM_SPOT_LIGHT_COORDS > 0
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_SPOT_LIGHT_COORDS; i ++ ) {
		shadowWorldPosition = worldPosition;
		#if ( defined( USE_SHADOWMAP ) && UNROLLED_LOOP_INDEX < NUM_SPOT_LIGHT_SHADOWS )
			shadowWorldPosition.xyz += shadowWorldNormal * spotLightShadows[ i ].shadowNormalBias;
		#endif
		vSpotLightCoord[ i ] = spotLightMatrix[ i ] * shadowWorldPosition;
	}
	#pragma unroll_loop_end
#endif`,kR=`float getShadowMask() {
	float shadow = 1.0;
	#ifdef USE_SHADOWMAP
	#if NUM_SUN_LIGHT_SHADOWS > 0
	SunLightShadow sunLight;
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_SUN_LIGHT_SHADOWS; i ++ ) {
		sunLight = sunLightShadows[ i ];
		shadow *= receiveShadow ? getSunShadow( sunShadowMap[ i ], sunLight, UNROLLED_LOOP_INDEX ) : 1.0;
	}
	#pragma unroll_loop_end
	#endif
	#if NUM_DIR_LIGHT_SHADOWS > 0
	DirectionalLightShadow directionalLight;
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_DIR_LIGHT_SHADOWS; i ++ ) {
		directionalLight = directionalLightShadows[ i ];
		shadow *= receiveShadow ? getShadow( directionalShadowMap[ i ], directionalLight.shadowMapSize, directionalLight.shadowIntensity, directionalLight.shadowBias, directionalLight.shadowRadius, vDirectionalShadowCoord[ i ] ) : 1.0;
	}
	#pragma unroll_loop_end
	#endif
	#if NUM_SPOT_LIGHT_SHADOWS > 0
	SpotLightShadow spotLight;
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_SPOT_LIGHT_SHADOWS; i ++ ) {
		spotLight = spotLightShadows[ i ];
		shadow *= receiveShadow ? getShadow( spotShadowMap[ i ], spotLight.shadowMapSize, spotLight.shadowIntensity, spotLight.shadowBias, spotLight.shadowRadius, vSpotLightCoord[ i ] ) : 1.0;
	}
	#pragma unroll_loop_end
	#endif
	#if NUM_POINT_LIGHT_SHADOWS > 0 && ( defined( SHADOWMAP_TYPE_PCF ) || defined( SHADOWMAP_TYPE_BASIC ) )
	PointLightShadow pointLight;
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_POINT_LIGHT_SHADOWS; i ++ ) {
		pointLight = pointLightShadows[ i ];
		shadow *= receiveShadow ? getPointShadow( pointShadowMap[ i ], pointLight.shadowMapSize, pointLight.shadowIntensity, pointLight.shadowBias, pointLight.shadowRadius, vPointShadowCoord[ i ], pointLight.shadowCameraNear, pointLight.shadowCameraFar ) : 1.0;
	}
	#pragma unroll_loop_end
	#endif
	#endif
	return shadow;
}`,VR=`#ifdef USE_SKINNING
	mat4 boneMatX = getBoneMatrix( skinIndex.x );
	mat4 boneMatY = getBoneMatrix( skinIndex.y );
	mat4 boneMatZ = getBoneMatrix( skinIndex.z );
	mat4 boneMatW = getBoneMatrix( skinIndex.w );
#endif`,GR=`#ifdef USE_SKINNING
	uniform mat4 bindMatrix;
	uniform mat4 bindMatrixInverse;
	uniform highp sampler2D boneTexture;
	mat4 getBoneMatrix( const in float i ) {
		int size = textureSize( boneTexture, 0 ).x;
		int j = int( i ) * 4;
		int x = j % size;
		int y = j / size;
		vec4 v1 = texelFetch( boneTexture, ivec2( x, y ), 0 );
		vec4 v2 = texelFetch( boneTexture, ivec2( x + 1, y ), 0 );
		vec4 v3 = texelFetch( boneTexture, ivec2( x + 2, y ), 0 );
		vec4 v4 = texelFetch( boneTexture, ivec2( x + 3, y ), 0 );
		return mat4( v1, v2, v3, v4 );
	}
#endif`,zR=`#ifdef USE_SKINNING
	vec4 skinVertex = bindMatrix * vec4( transformed, 1.0 );
	vec4 skinned = vec4( 0.0 );
	skinned += boneMatX * skinVertex * skinWeight.x;
	skinned += boneMatY * skinVertex * skinWeight.y;
	skinned += boneMatZ * skinVertex * skinWeight.z;
	skinned += boneMatW * skinVertex * skinWeight.w;
	transformed = ( bindMatrixInverse * skinned ).xyz;
#endif`,HR=`#ifdef USE_SKINNING
	mat4 skinMatrix = mat4( 0.0 );
	skinMatrix += skinWeight.x * boneMatX;
	skinMatrix += skinWeight.y * boneMatY;
	skinMatrix += skinWeight.z * boneMatZ;
	skinMatrix += skinWeight.w * boneMatW;
	skinMatrix = bindMatrixInverse * skinMatrix * bindMatrix;
	objectNormal = vec4( skinMatrix * vec4( objectNormal, 0.0 ) ).xyz;
	#ifdef USE_TANGENT
		objectTangent = vec4( skinMatrix * vec4( objectTangent, 0.0 ) ).xyz;
	#endif
#endif`,WR=`float specularStrength;
#ifdef USE_SPECULARMAP
	vec4 texelSpecular = texture2D( specularMap, vSpecularMapUv );
	specularStrength = texelSpecular.r;
#else
	specularStrength = 1.0;
#endif`,XR=`#ifdef USE_SPECULARMAP
	uniform sampler2D specularMap;
#endif`,YR=`#if defined( TONE_MAPPING )
	gl_FragColor.rgb = toneMapping( gl_FragColor.rgb );
#endif`,ZR=`#ifndef saturate
#define saturate( a ) clamp( a, 0.0, 1.0 )
#endif
uniform float toneMappingExposure;
vec3 LinearToneMapping( vec3 color ) {
	return saturate( toneMappingExposure * color );
}
vec3 ReinhardToneMapping( vec3 color ) {
	color *= toneMappingExposure;
	return saturate( color / ( vec3( 1.0 ) + color ) );
}
vec3 CineonToneMapping( vec3 color ) {
	color *= toneMappingExposure;
	color = max( vec3( 0.0 ), color - 0.004 );
	return pow( ( color * ( 6.2 * color + 0.5 ) ) / ( color * ( 6.2 * color + 1.7 ) + 0.06 ), vec3( 2.2 ) );
}
vec3 RRTAndODTFit( vec3 v ) {
	vec3 a = v * ( v + 0.0245786 ) - 0.000090537;
	vec3 b = v * ( 0.983729 * v + 0.4329510 ) + 0.238081;
	return a / b;
}
vec3 ACESFilmicToneMapping( vec3 color ) {
	const mat3 ACESInputMat = mat3(
		vec3( 0.59719, 0.07600, 0.02840 ),		vec3( 0.35458, 0.90834, 0.13383 ),
		vec3( 0.04823, 0.01566, 0.83777 )
	);
	const mat3 ACESOutputMat = mat3(
		vec3(  1.60475, -0.10208, -0.00327 ),		vec3( -0.53108,  1.10813, -0.07276 ),
		vec3( -0.07367, -0.00605,  1.07602 )
	);
	color *= toneMappingExposure / 0.6;
	color = ACESInputMat * color;
	color = RRTAndODTFit( color );
	color = ACESOutputMat * color;
	return saturate( color );
}
const mat3 LINEAR_REC2020_TO_LINEAR_SRGB = mat3(
	vec3( 1.6605, - 0.1246, - 0.0182 ),
	vec3( - 0.5876, 1.1329, - 0.1006 ),
	vec3( - 0.0728, - 0.0083, 1.1187 )
);
const mat3 LINEAR_SRGB_TO_LINEAR_REC2020 = mat3(
	vec3( 0.6274, 0.0691, 0.0164 ),
	vec3( 0.3293, 0.9195, 0.0880 ),
	vec3( 0.0433, 0.0113, 0.8956 )
);
vec3 agxDefaultContrastApprox( vec3 x ) {
	vec3 x2 = x * x;
	vec3 x4 = x2 * x2;
	return + 15.5 * x4 * x2
		- 40.14 * x4 * x
		+ 31.96 * x4
		- 6.868 * x2 * x
		+ 0.4298 * x2
		+ 0.1191 * x
		- 0.00232;
}
vec3 AgXToneMapping( vec3 color ) {
	const mat3 AgXInsetMatrix = mat3(
		vec3( 0.856627153315983, 0.137318972929847, 0.11189821299995 ),
		vec3( 0.0951212405381588, 0.761241990602591, 0.0767994186031903 ),
		vec3( 0.0482516061458583, 0.101439036467562, 0.811302368396859 )
	);
	const mat3 AgXOutsetMatrix = mat3(
		vec3( 1.1271005818144368, - 0.1413297634984383, - 0.14132976349843826 ),
		vec3( - 0.11060664309660323, 1.157823702216272, - 0.11060664309660294 ),
		vec3( - 0.016493938717834573, - 0.016493938717834257, 1.2519364065950405 )
	);
	const float AgxMinEv = - 12.47393;	const float AgxMaxEv = 4.026069;
	color *= toneMappingExposure;
	color = LINEAR_SRGB_TO_LINEAR_REC2020 * color;
	color = AgXInsetMatrix * color;
	color = max( color, 1e-10 );	color = log2( color );
	color = ( color - AgxMinEv ) / ( AgxMaxEv - AgxMinEv );
	color = clamp( color, 0.0, 1.0 );
	color = agxDefaultContrastApprox( color );
	color = AgXOutsetMatrix * color;
	color = pow( max( vec3( 0.0 ), color ), vec3( 2.2 ) );
	color = LINEAR_REC2020_TO_LINEAR_SRGB * color;
	color = clamp( color, 0.0, 1.0 );
	return color;
}
vec3 NeutralToneMapping( vec3 color ) {
	const float StartCompression = 0.8 - 0.04;
	const float Desaturation = 0.15;
	color *= toneMappingExposure;
	float x = min( color.r, min( color.g, color.b ) );
	float offset = x < 0.08 ? x - 6.25 * x * x : 0.04;
	color -= offset;
	float peak = max( color.r, max( color.g, color.b ) );
	if ( peak < StartCompression ) return color;
	float d = 1. - StartCompression;
	float newPeak = 1. - d * d / ( peak + d - StartCompression );
	color *= newPeak / peak;
	float g = 1. - 1. / ( Desaturation * ( peak - newPeak ) + 1. );
	return mix( color, vec3( newPeak ), g );
}
vec3 CustomToneMapping( vec3 color ) { return color; }`,KR=`#ifdef USE_TRANSMISSION
	material.transmission = transmission;
	material.transmissionAlpha = 1.0;
	material.thickness = thickness;
	material.attenuationDistance = attenuationDistance;
	material.attenuationColor = attenuationColor;
	#ifdef USE_TRANSMISSIONMAP
		material.transmission *= texture2D( transmissionMap, vTransmissionMapUv ).r;
	#endif
	#ifdef USE_THICKNESSMAP
		material.thickness *= texture2D( thicknessMap, vThicknessMapUv ).g;
	#endif
	vec3 pos = vWorldPosition;
	vec3 v = normalize( cameraPosition - pos );
	vec3 n = transformNormalByInverseViewMatrix( normal, viewMatrix );
	vec4 transmitted = getIBLVolumeRefraction(
		n, v, material.roughness, material.diffuseContribution, material.specularColorBlended, material.specularF90,
		pos, modelMatrix, viewMatrix, projectionMatrix, material.dispersion, material.ior, material.thickness,
		material.attenuationColor, material.attenuationDistance );
	material.transmissionAlpha = mix( material.transmissionAlpha, transmitted.a, material.transmission );
	totalDiffuse = mix( totalDiffuse, transmitted.rgb, material.transmission );
#endif`,$R=`#ifdef USE_TRANSMISSION
	uniform float transmission;
	uniform float thickness;
	uniform float attenuationDistance;
	uniform vec3 attenuationColor;
	#ifdef USE_TRANSMISSIONMAP
		uniform sampler2D transmissionMap;
	#endif
	#ifdef USE_THICKNESSMAP
		uniform sampler2D thicknessMap;
	#endif
	uniform vec2 transmissionSamplerSize;
	uniform sampler2D transmissionSamplerMap;
	uniform mat4 modelMatrix;
	uniform mat4 projectionMatrix;
	varying vec3 vWorldPosition;
	float w0( float a ) {
		return ( 1.0 / 6.0 ) * ( a * ( a * ( - a + 3.0 ) - 3.0 ) + 1.0 );
	}
	float w1( float a ) {
		return ( 1.0 / 6.0 ) * ( a *  a * ( 3.0 * a - 6.0 ) + 4.0 );
	}
	float w2( float a ){
		return ( 1.0 / 6.0 ) * ( a * ( a * ( - 3.0 * a + 3.0 ) + 3.0 ) + 1.0 );
	}
	float w3( float a ) {
		return ( 1.0 / 6.0 ) * ( a * a * a );
	}
	float g0( float a ) {
		return w0( a ) + w1( a );
	}
	float g1( float a ) {
		return w2( a ) + w3( a );
	}
	float h0( float a ) {
		return - 1.0 + w1( a ) / ( w0( a ) + w1( a ) );
	}
	float h1( float a ) {
		return 1.0 + w3( a ) / ( w2( a ) + w3( a ) );
	}
	vec4 bicubic( sampler2D tex, vec2 uv, vec4 texelSize, float lod ) {
		uv = uv * texelSize.zw + 0.5;
		vec2 iuv = floor( uv );
		vec2 fuv = fract( uv );
		float g0x = g0( fuv.x );
		float g1x = g1( fuv.x );
		float h0x = h0( fuv.x );
		float h1x = h1( fuv.x );
		float h0y = h0( fuv.y );
		float h1y = h1( fuv.y );
		vec2 p0 = ( vec2( iuv.x + h0x, iuv.y + h0y ) - 0.5 ) * texelSize.xy;
		vec2 p1 = ( vec2( iuv.x + h1x, iuv.y + h0y ) - 0.5 ) * texelSize.xy;
		vec2 p2 = ( vec2( iuv.x + h0x, iuv.y + h1y ) - 0.5 ) * texelSize.xy;
		vec2 p3 = ( vec2( iuv.x + h1x, iuv.y + h1y ) - 0.5 ) * texelSize.xy;
		return g0( fuv.y ) * ( g0x * textureLod( tex, p0, lod ) + g1x * textureLod( tex, p1, lod ) ) +
			g1( fuv.y ) * ( g0x * textureLod( tex, p2, lod ) + g1x * textureLod( tex, p3, lod ) );
	}
	vec4 textureBicubic( sampler2D sampler, vec2 uv, float lod ) {
		vec2 fLodSize = vec2( textureSize( sampler, int( lod ) ) );
		vec2 cLodSize = vec2( textureSize( sampler, int( lod + 1.0 ) ) );
		vec2 fLodSizeInv = 1.0 / fLodSize;
		vec2 cLodSizeInv = 1.0 / cLodSize;
		vec4 fSample = bicubic( sampler, uv, vec4( fLodSizeInv, fLodSize ), floor( lod ) );
		vec4 cSample = bicubic( sampler, uv, vec4( cLodSizeInv, cLodSize ), ceil( lod ) );
		return mix( fSample, cSample, fract( lod ) );
	}
	vec3 getVolumeTransmissionRay( const in vec3 n, const in vec3 v, const in float thickness, const in float ior, const in mat4 modelMatrix ) {
		vec3 refractionVector = refract( - v, normalize( n ), 1.0 / ior );
		vec3 modelScale;
		modelScale.x = length( vec3( modelMatrix[ 0 ].xyz ) );
		modelScale.y = length( vec3( modelMatrix[ 1 ].xyz ) );
		modelScale.z = length( vec3( modelMatrix[ 2 ].xyz ) );
		return normalize( refractionVector ) * thickness * modelScale;
	}
	float applyIorToRoughness( const in float roughness, const in float ior ) {
		return roughness * clamp( ior * 2.0 - 2.0, 0.0, 1.0 );
	}
	vec4 getTransmissionSample( const in vec2 fragCoord, const in float roughness, const in float ior ) {
		float lod = log2( transmissionSamplerSize.x ) * applyIorToRoughness( roughness, ior );
		return textureBicubic( transmissionSamplerMap, fragCoord.xy, lod );
	}
	vec3 volumeAttenuation( const in float transmissionDistance, const in vec3 attenuationColor, const in float attenuationDistance ) {
		if ( isinf( attenuationDistance ) ) {
			return vec3( 1.0 );
		} else {
			vec3 attenuationCoefficient = -log( attenuationColor ) / attenuationDistance;
			vec3 transmittance = exp( - attenuationCoefficient * transmissionDistance );			return transmittance;
		}
	}
	vec4 getIBLVolumeRefraction( const in vec3 n, const in vec3 v, const in float roughness, const in vec3 diffuseColor,
		const in vec3 specularColor, const in float specularF90, const in vec3 position, const in mat4 modelMatrix,
		const in mat4 viewMatrix, const in mat4 projMatrix, const in float dispersion, const in float ior, const in float thickness,
		const in vec3 attenuationColor, const in float attenuationDistance ) {
		vec4 transmittedLight;
		vec3 transmittance;
		#ifdef USE_DISPERSION
			float halfSpread = ( ior - 1.0 ) * 0.025 * dispersion;
			vec3 iors = vec3( ior - halfSpread, ior, ior + halfSpread );
			for ( int i = 0; i < 3; i ++ ) {
				vec3 transmissionRay = getVolumeTransmissionRay( n, v, thickness, iors[ i ], modelMatrix );
				vec3 refractedRayExit = position + transmissionRay;
				vec4 ndcPos = projMatrix * viewMatrix * vec4( refractedRayExit, 1.0 );
				vec2 refractionCoords = ndcPos.xy / ndcPos.w;
				refractionCoords += 1.0;
				refractionCoords /= 2.0;
				vec4 transmissionSample = getTransmissionSample( refractionCoords, roughness, iors[ i ] );
				transmittedLight[ i ] = transmissionSample[ i ];
				transmittedLight.a += transmissionSample.a;
				transmittance[ i ] = diffuseColor[ i ] * volumeAttenuation( length( transmissionRay ), attenuationColor, attenuationDistance )[ i ];
			}
			transmittedLight.a /= 3.0;
		#else
			vec3 transmissionRay = getVolumeTransmissionRay( n, v, thickness, ior, modelMatrix );
			vec3 refractedRayExit = position + transmissionRay;
			vec4 ndcPos = projMatrix * viewMatrix * vec4( refractedRayExit, 1.0 );
			vec2 refractionCoords = ndcPos.xy / ndcPos.w;
			refractionCoords += 1.0;
			refractionCoords /= 2.0;
			transmittedLight = getTransmissionSample( refractionCoords, roughness, ior );
			transmittance = diffuseColor * volumeAttenuation( length( transmissionRay ), attenuationColor, attenuationDistance );
		#endif
		vec3 attenuatedColor = transmittance * transmittedLight.rgb;
		vec3 F = EnvironmentBRDF( n, v, specularColor, specularF90, roughness );
		float transmittanceFactor = ( transmittance.r + transmittance.g + transmittance.b ) / 3.0;
		return vec4( ( 1.0 - F ) * attenuatedColor, 1.0 - ( 1.0 - transmittedLight.a ) * transmittanceFactor );
	}
#endif`,qR=`#if defined( USE_UV ) || defined( USE_ANISOTROPY )
	varying vec2 vUv;
#endif
#ifdef USE_MAP
	varying vec2 vMapUv;
#endif
#ifdef USE_ALPHAMAP
	varying vec2 vAlphaMapUv;
#endif
#ifdef USE_LIGHTMAP
	varying vec2 vLightMapUv;
#endif
#ifdef USE_AOMAP
	varying vec2 vAoMapUv;
#endif
#ifdef USE_BUMPMAP
	varying vec2 vBumpMapUv;
#endif
#ifdef USE_NORMALMAP
	varying vec2 vNormalMapUv;
#endif
#ifdef USE_EMISSIVEMAP
	varying vec2 vEmissiveMapUv;
#endif
#ifdef USE_METALNESSMAP
	varying vec2 vMetalnessMapUv;
#endif
#ifdef USE_ROUGHNESSMAP
	varying vec2 vRoughnessMapUv;
#endif
#ifdef USE_DIFFUSE_ROUGHNESSMAP
	varying vec2 vDiffuseRoughnessMapUv;
#endif
#ifdef USE_ANISOTROPYMAP
	varying vec2 vAnisotropyMapUv;
#endif
#ifdef USE_CLEARCOATMAP
	varying vec2 vClearcoatMapUv;
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	varying vec2 vClearcoatNormalMapUv;
#endif
#ifdef USE_CLEARCOAT_ROUGHNESSMAP
	varying vec2 vClearcoatRoughnessMapUv;
#endif
#ifdef USE_IRIDESCENCEMAP
	varying vec2 vIridescenceMapUv;
#endif
#ifdef USE_IRIDESCENCE_THICKNESSMAP
	varying vec2 vIridescenceThicknessMapUv;
#endif
#ifdef USE_SHEEN_COLORMAP
	varying vec2 vSheenColorMapUv;
#endif
#ifdef USE_SHEEN_ROUGHNESSMAP
	varying vec2 vSheenRoughnessMapUv;
#endif
#ifdef USE_SPECULARMAP
	varying vec2 vSpecularMapUv;
#endif
#ifdef USE_SPECULAR_COLORMAP
	varying vec2 vSpecularColorMapUv;
#endif
#ifdef USE_SPECULAR_INTENSITYMAP
	varying vec2 vSpecularIntensityMapUv;
#endif
#ifdef USE_TRANSMISSIONMAP
	uniform mat3 transmissionMapTransform;
	varying vec2 vTransmissionMapUv;
#endif
#ifdef USE_THICKNESSMAP
	uniform mat3 thicknessMapTransform;
	varying vec2 vThicknessMapUv;
#endif`,JR=`#if defined( USE_UV ) || defined( USE_ANISOTROPY )
	varying vec2 vUv;
#endif
#ifdef USE_MAP
	uniform mat3 mapTransform;
	varying vec2 vMapUv;
#endif
#ifdef USE_ALPHAMAP
	uniform mat3 alphaMapTransform;
	varying vec2 vAlphaMapUv;
#endif
#ifdef USE_LIGHTMAP
	uniform mat3 lightMapTransform;
	varying vec2 vLightMapUv;
#endif
#ifdef USE_AOMAP
	uniform mat3 aoMapTransform;
	varying vec2 vAoMapUv;
#endif
#ifdef USE_BUMPMAP
	uniform mat3 bumpMapTransform;
	varying vec2 vBumpMapUv;
#endif
#ifdef USE_NORMALMAP
	uniform mat3 normalMapTransform;
	varying vec2 vNormalMapUv;
#endif
#ifdef USE_DISPLACEMENTMAP
	uniform mat3 displacementMapTransform;
	varying vec2 vDisplacementMapUv;
#endif
#ifdef USE_EMISSIVEMAP
	uniform mat3 emissiveMapTransform;
	varying vec2 vEmissiveMapUv;
#endif
#ifdef USE_METALNESSMAP
	uniform mat3 metalnessMapTransform;
	varying vec2 vMetalnessMapUv;
#endif
#ifdef USE_ROUGHNESSMAP
	uniform mat3 roughnessMapTransform;
	varying vec2 vRoughnessMapUv;
#endif
#ifdef USE_DIFFUSE_ROUGHNESSMAP
	uniform mat3 diffuseRoughnessMapTransform;
	varying vec2 vDiffuseRoughnessMapUv;
#endif
#ifdef USE_ANISOTROPYMAP
	uniform mat3 anisotropyMapTransform;
	varying vec2 vAnisotropyMapUv;
#endif
#ifdef USE_CLEARCOATMAP
	uniform mat3 clearcoatMapTransform;
	varying vec2 vClearcoatMapUv;
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	uniform mat3 clearcoatNormalMapTransform;
	varying vec2 vClearcoatNormalMapUv;
#endif
#ifdef USE_CLEARCOAT_ROUGHNESSMAP
	uniform mat3 clearcoatRoughnessMapTransform;
	varying vec2 vClearcoatRoughnessMapUv;
#endif
#ifdef USE_SHEEN_COLORMAP
	uniform mat3 sheenColorMapTransform;
	varying vec2 vSheenColorMapUv;
#endif
#ifdef USE_SHEEN_ROUGHNESSMAP
	uniform mat3 sheenRoughnessMapTransform;
	varying vec2 vSheenRoughnessMapUv;
#endif
#ifdef USE_IRIDESCENCEMAP
	uniform mat3 iridescenceMapTransform;
	varying vec2 vIridescenceMapUv;
#endif
#ifdef USE_IRIDESCENCE_THICKNESSMAP
	uniform mat3 iridescenceThicknessMapTransform;
	varying vec2 vIridescenceThicknessMapUv;
#endif
#ifdef USE_SPECULARMAP
	uniform mat3 specularMapTransform;
	varying vec2 vSpecularMapUv;
#endif
#ifdef USE_SPECULAR_COLORMAP
	uniform mat3 specularColorMapTransform;
	varying vec2 vSpecularColorMapUv;
#endif
#ifdef USE_SPECULAR_INTENSITYMAP
	uniform mat3 specularIntensityMapTransform;
	varying vec2 vSpecularIntensityMapUv;
#endif
#ifdef USE_TRANSMISSIONMAP
	uniform mat3 transmissionMapTransform;
	varying vec2 vTransmissionMapUv;
#endif
#ifdef USE_THICKNESSMAP
	uniform mat3 thicknessMapTransform;
	varying vec2 vThicknessMapUv;
#endif`,jR=`#if defined( USE_UV ) || defined( USE_ANISOTROPY )
	vUv = vec3( uv, 1 ).xy;
#endif
#ifdef USE_MAP
	vMapUv = ( mapTransform * vec3( MAP_UV, 1 ) ).xy;
#endif
#ifdef USE_ALPHAMAP
	vAlphaMapUv = ( alphaMapTransform * vec3( ALPHAMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_LIGHTMAP
	vLightMapUv = ( lightMapTransform * vec3( LIGHTMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_AOMAP
	vAoMapUv = ( aoMapTransform * vec3( AOMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_BUMPMAP
	vBumpMapUv = ( bumpMapTransform * vec3( BUMPMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_NORMALMAP
	vNormalMapUv = ( normalMapTransform * vec3( NORMALMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_DISPLACEMENTMAP
	vDisplacementMapUv = ( displacementMapTransform * vec3( DISPLACEMENTMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_EMISSIVEMAP
	vEmissiveMapUv = ( emissiveMapTransform * vec3( EMISSIVEMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_METALNESSMAP
	vMetalnessMapUv = ( metalnessMapTransform * vec3( METALNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_ROUGHNESSMAP
	vRoughnessMapUv = ( roughnessMapTransform * vec3( ROUGHNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_DIFFUSE_ROUGHNESSMAP
	vDiffuseRoughnessMapUv = ( diffuseRoughnessMapTransform * vec3( DIFFUSE_ROUGHNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_ANISOTROPYMAP
	vAnisotropyMapUv = ( anisotropyMapTransform * vec3( ANISOTROPYMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_CLEARCOATMAP
	vClearcoatMapUv = ( clearcoatMapTransform * vec3( CLEARCOATMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	vClearcoatNormalMapUv = ( clearcoatNormalMapTransform * vec3( CLEARCOAT_NORMALMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_CLEARCOAT_ROUGHNESSMAP
	vClearcoatRoughnessMapUv = ( clearcoatRoughnessMapTransform * vec3( CLEARCOAT_ROUGHNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_IRIDESCENCEMAP
	vIridescenceMapUv = ( iridescenceMapTransform * vec3( IRIDESCENCEMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_IRIDESCENCE_THICKNESSMAP
	vIridescenceThicknessMapUv = ( iridescenceThicknessMapTransform * vec3( IRIDESCENCE_THICKNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_SHEEN_COLORMAP
	vSheenColorMapUv = ( sheenColorMapTransform * vec3( SHEEN_COLORMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_SHEEN_ROUGHNESSMAP
	vSheenRoughnessMapUv = ( sheenRoughnessMapTransform * vec3( SHEEN_ROUGHNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_SPECULARMAP
	vSpecularMapUv = ( specularMapTransform * vec3( SPECULARMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_SPECULAR_COLORMAP
	vSpecularColorMapUv = ( specularColorMapTransform * vec3( SPECULAR_COLORMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_SPECULAR_INTENSITYMAP
	vSpecularIntensityMapUv = ( specularIntensityMapTransform * vec3( SPECULAR_INTENSITYMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_TRANSMISSIONMAP
	vTransmissionMapUv = ( transmissionMapTransform * vec3( TRANSMISSIONMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_THICKNESSMAP
	vThicknessMapUv = ( thicknessMapTransform * vec3( THICKNESSMAP_UV, 1 ) ).xy;
#endif`,QR=`#if defined( USE_ENVMAP ) || defined( DISTANCE ) || defined ( USE_SHADOWMAP ) || defined ( USE_TRANSMISSION ) || NUM_SPOT_LIGHT_COORDS > 0
	vec4 worldPosition = vec4( transformed, 1.0 );
	#ifdef USE_BATCHING
		worldPosition = batchingMatrix * worldPosition;
	#endif
	#ifdef USE_INSTANCING
		worldPosition = instanceMatrix * worldPosition;
	#endif
	worldPosition = modelMatrix * worldPosition;
#endif`,eI=`varying vec2 vUv;
uniform mat3 uvTransform;
void main() {
	vUv = ( uvTransform * vec3( uv, 1 ) ).xy;
	gl_Position = vec4( position.xy, 1.0, 1.0 );
}`,tI=`uniform sampler2D t2D;
uniform float backgroundIntensity;
varying vec2 vUv;
void main() {
	vec4 texColor = texture2D( t2D, vUv );
	#ifdef DECODE_VIDEO_TEXTURE
		texColor = vec4( mix( pow( texColor.rgb * 0.9478672986 + vec3( 0.0521327014 ), vec3( 2.4 ) ), texColor.rgb * 0.0773993808, vec3( lessThanEqual( texColor.rgb, vec3( 0.04045 ) ) ) ), texColor.w );
	#endif
	texColor.rgb *= backgroundIntensity;
	gl_FragColor = texColor;
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
}`,nI=`varying vec3 vWorldDirection;
#include <common>
void main() {
	vWorldDirection = transformDirection( position, modelMatrix );
	#include <begin_vertex>
	#include <project_vertex>
	gl_Position.z = gl_Position.w;
}`,iI=`uniform float backgroundBlurriness;
uniform float backgroundIntensity;
uniform mat3 backgroundRotation;
varying vec3 vWorldDirection;
#include <envmap_common_pars_fragment>
void main() {
	#ifdef ENVMAP_TYPE_PMREM
		vec4 texColor = textureLod( envMap, backgroundRotation * vWorldDirection, roughnessToMip( backgroundBlurriness ) );
	#else
		vec4 texColor = textureCube( envMap, backgroundRotation * vWorldDirection );
	#endif
	texColor.rgb *= backgroundIntensity;
	gl_FragColor = texColor;
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
}`,rI=`varying vec3 vWorldDirection;
#include <common>
void main() {
	vWorldDirection = transformDirection( position, modelMatrix );
	#include <begin_vertex>
	#include <project_vertex>
	gl_Position.z = gl_Position.w;
}`,sI=`uniform samplerCube tCube;
uniform float tFlip;
uniform float opacity;
varying vec3 vWorldDirection;
void main() {
	vec4 texColor = textureCube( tCube, vec3( tFlip * vWorldDirection.x, vWorldDirection.yz ) );
	gl_FragColor = texColor;
	gl_FragColor.a *= opacity;
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
}`,oI=`#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
varying vec2 vHighPrecisionZW;
void main() {
	#include <uv_vertex>
	#include <batching_vertex>
	#include <skinbase_vertex>
	#include <morphinstance_vertex>
	#ifdef USE_DISPLACEMENTMAP
		#include <beginnormal_vertex>
		#include <morphnormal_vertex>
		#include <skinnormal_vertex>
	#endif
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	vHighPrecisionZW = gl_Position.zw;
}`,aI=`#if DEPTH_PACKING == 3200
	uniform float opacity;
#endif
#include <common>
#include <packing>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
varying vec2 vHighPrecisionZW;
void main() {
	vec4 diffuseColor = vec4( 1.0 );
	#include <clipping_planes_fragment>
	#if DEPTH_PACKING == 3200
		diffuseColor.a = opacity;
	#endif
	#include <map_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <logdepthbuf_fragment>
	#ifdef USE_REVERSED_DEPTH_BUFFER
		float fragCoordZ = vHighPrecisionZW[ 0 ] / vHighPrecisionZW[ 1 ];
	#else
		float fragCoordZ = 0.5 * vHighPrecisionZW[ 0 ] / vHighPrecisionZW[ 1 ] + 0.5;
	#endif
	#if DEPTH_PACKING == 3200
		gl_FragColor = vec4( vec3( 1.0 - fragCoordZ ), opacity );
	#elif DEPTH_PACKING == 3201
		gl_FragColor = packDepthToRGBA( fragCoordZ );
	#elif DEPTH_PACKING == 3202
		gl_FragColor = vec4( packDepthToRGB( fragCoordZ ), 1.0 );
	#elif DEPTH_PACKING == 3203
		gl_FragColor = vec4( packDepthToRG( fragCoordZ ), 0.0, 1.0 );
	#endif
}`,lI=`#define DISTANCE
varying vec3 vWorldPosition;
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <batching_vertex>
	#include <skinbase_vertex>
	#include <morphinstance_vertex>
	#ifdef USE_DISPLACEMENTMAP
		#include <beginnormal_vertex>
		#include <morphnormal_vertex>
		#include <skinnormal_vertex>
	#endif
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <worldpos_vertex>
	#include <clipping_planes_vertex>
	vWorldPosition = worldPosition.xyz;
}`,cI=`#define DISTANCE
uniform vec3 referencePosition;
uniform float nearDistance;
uniform float farDistance;
varying vec3 vWorldPosition;
#include <common>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( 1.0 );
	#include <clipping_planes_fragment>
	#include <map_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	float dist = length( vWorldPosition - referencePosition );
	dist = ( dist - nearDistance ) / ( farDistance - nearDistance );
	dist = saturate( dist );
	gl_FragColor = vec4( dist, 0.0, 0.0, 1.0 );
}`,uI=`varying vec3 vWorldDirection;
#include <common>
void main() {
	vWorldDirection = transformDirection( position, modelMatrix );
	#include <begin_vertex>
	#include <project_vertex>
}`,hI=`uniform sampler2D tEquirect;
varying vec3 vWorldDirection;
#include <common>
void main() {
	vec3 direction = normalize( vWorldDirection );
	vec2 sampleUV = equirectUv( direction );
	gl_FragColor = texture2D( tEquirect, sampleUV );
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
}`,fI=`uniform float scale;
attribute float lineDistance;
varying float vLineDistance;
#include <common>
#include <uv_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <morphtarget_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	vLineDistance = scale * lineDistance;
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	#include <fog_vertex>
}`,dI=`uniform vec3 diffuse;
uniform float opacity;
uniform float dashSize;
uniform float totalSize;
varying float vLineDistance;
#include <common>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <fog_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	if ( mod( vLineDistance, totalSize ) > dashSize ) {
		discard;
	}
	vec3 outgoingLight = vec3( 0.0 );
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	outgoingLight = diffuseColor.rgb;
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
}`,pI=`#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <envmap_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#if defined ( USE_ENVMAP ) || defined ( USE_SKINNING )
		#include <beginnormal_vertex>
		#include <morphnormal_vertex>
		#include <skinbase_vertex>
		#include <skinnormal_vertex>
		#include <defaultnormal_vertex>
	#endif
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	#include <worldpos_vertex>
	#include <envmap_vertex>
	#include <fog_vertex>
}`,mI=`uniform vec3 diffuse;
uniform float opacity;
#ifndef FLAT_SHADED
	varying vec3 vNormal;
#endif
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <aomap_pars_fragment>
#include <lightmap_pars_fragment>
#include <envmap_common_pars_fragment>
#include <envmap_pars_fragment>
#include <fog_pars_fragment>
#include <specularmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <specularmap_fragment>
	ReflectedLight reflectedLight = ReflectedLight( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ) );
	#ifdef USE_LIGHTMAP
		vec4 lightMapTexel = texture2D( lightMap, vLightMapUv );
		reflectedLight.indirectDiffuse += lightMapTexel.rgb * lightMapIntensity * RECIPROCAL_PI;
	#else
		reflectedLight.indirectDiffuse += vec3( 1.0 );
	#endif
	#include <aomap_fragment>
	reflectedLight.indirectDiffuse *= diffuseColor.rgb;
	vec3 outgoingLight = reflectedLight.indirectDiffuse;
	#include <envmap_fragment>
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,gI=`#define LAMBERT
varying vec3 vViewPosition;
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <envmap_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <shadowmap_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	vViewPosition = - mvPosition.xyz;
	#include <worldpos_vertex>
	#include <envmap_vertex>
	#include <shadowmap_vertex>
	#include <fog_vertex>
}`,_I=`#define LAMBERT
uniform vec3 diffuse;
uniform vec3 emissive;
uniform float opacity;
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <aomap_pars_fragment>
#include <lightmap_pars_fragment>
#include <emissivemap_pars_fragment>
#include <envmap_common_pars_fragment>
#include <envmap_pars_fragment>
#include <envmap_physical_pars_fragment>
#include <fog_pars_fragment>
#include <bsdfs>
#include <lights_pars_begin>
#include <normal_pars_fragment>
#include <lights_lambert_pars_fragment>
#include <shadowmap_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <specularmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	ReflectedLight reflectedLight = ReflectedLight( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ) );
	vec3 totalEmissiveRadiance = emissive;
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <specularmap_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	#include <emissivemap_fragment>
	#include <lights_lambert_fragment>
	#include <lights_fragment_begin>
	#include <lights_fragment_maps>
	#include <lights_fragment_end>
	#include <aomap_fragment>
	vec3 outgoingLight = reflectedLight.directDiffuse + reflectedLight.indirectDiffuse + totalEmissiveRadiance;
	#include <envmap_fragment>
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,yI=`#define MATCAP
varying vec3 vViewPosition;
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <color_pars_vertex>
#include <displacementmap_pars_vertex>
#include <fog_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	#include <fog_vertex>
	vViewPosition = - mvPosition.xyz;
}`,xI=`#define MATCAP
uniform vec3 diffuse;
uniform float opacity;
uniform sampler2D matcap;
varying vec3 vViewPosition;
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <fog_pars_fragment>
#include <normal_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	vec3 viewDir = normalize( vViewPosition );
	vec3 x = normalize( vec3( viewDir.z, 0.0, - viewDir.x ) );
	vec3 y = cross( viewDir, x );
	vec2 uv = vec2( dot( x, normal ), dot( y, normal ) ) * 0.495 + 0.5;
	#ifdef USE_MATCAP
		vec4 matcapColor = texture2D( matcap, uv );
	#else
		vec4 matcapColor = vec4( vec3( mix( 0.2, 0.8, uv.y ) ), 1.0 );
	#endif
	vec3 outgoingLight = diffuseColor.rgb * matcapColor.rgb;
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,bI=`#define NORMAL
#if defined( FLAT_SHADED ) || defined( USE_BUMPMAP ) || defined( USE_NORMALMAP_TANGENTSPACE )
	varying vec3 vViewPosition;
#endif
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphinstance_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
#if defined( FLAT_SHADED ) || defined( USE_BUMPMAP ) || defined( USE_NORMALMAP_TANGENTSPACE )
	vViewPosition = - mvPosition.xyz;
#endif
}`,vI=`#define NORMAL
uniform float opacity;
#if defined( FLAT_SHADED ) || defined( USE_BUMPMAP ) || defined( USE_NORMALMAP_TANGENTSPACE )
	varying vec3 vViewPosition;
#endif
#include <uv_pars_fragment>
#include <normal_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( 0.0, 0.0, 0.0, opacity );
	#include <clipping_planes_fragment>
	#include <logdepthbuf_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	gl_FragColor = vec4( normalize( normal ) * 0.5 + 0.5, diffuseColor.a );
	#ifdef OPAQUE
		gl_FragColor.a = 1.0;
	#endif
}`,SI=`#define PHONG
varying vec3 vViewPosition;
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <envmap_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <shadowmap_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphinstance_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	vViewPosition = - mvPosition.xyz;
	#include <worldpos_vertex>
	#include <envmap_vertex>
	#include <shadowmap_vertex>
	#include <fog_vertex>
}`,EI=`#define PHONG
uniform vec3 diffuse;
uniform vec3 emissive;
uniform vec3 specular;
uniform float shininess;
uniform float opacity;
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <aomap_pars_fragment>
#include <lightmap_pars_fragment>
#include <emissivemap_pars_fragment>
#include <envmap_common_pars_fragment>
#include <envmap_pars_fragment>
#include <envmap_physical_pars_fragment>
#include <fog_pars_fragment>
#include <bsdfs>
#include <lights_pars_begin>
#include <normal_pars_fragment>
#include <lights_phong_pars_fragment>
#include <shadowmap_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <specularmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	ReflectedLight reflectedLight = ReflectedLight( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ) );
	vec3 totalEmissiveRadiance = emissive;
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <specularmap_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	#include <emissivemap_fragment>
	#include <lights_phong_fragment>
	#include <lights_fragment_begin>
	#include <lights_fragment_maps>
	#include <lights_fragment_end>
	#include <aomap_fragment>
	vec3 outgoingLight = reflectedLight.directDiffuse + reflectedLight.indirectDiffuse + reflectedLight.directSpecular + reflectedLight.indirectSpecular + totalEmissiveRadiance;
	#include <envmap_fragment>
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,MI=`#define STANDARD
varying vec3 vViewPosition;
#ifdef USE_TRANSMISSION
	varying vec3 vWorldPosition;
#endif
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <shadowmap_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	vViewPosition = - mvPosition.xyz;
	#include <worldpos_vertex>
	#include <shadowmap_vertex>
	#include <fog_vertex>
#ifdef USE_TRANSMISSION
	vWorldPosition = worldPosition.xyz;
#endif
}`,wI=`#define STANDARD
#ifdef PHYSICAL
	#define IOR
	#define USE_SPECULAR
#endif
uniform vec3 diffuse;
uniform vec3 emissive;
uniform float roughness;
uniform float metalness;
uniform float opacity;
#ifdef IOR
	uniform float ior;
#endif
#ifdef USE_SPECULAR
	uniform float specularIntensity;
	uniform vec3 specularColor;
	#ifdef USE_SPECULAR_COLORMAP
		uniform sampler2D specularColorMap;
	#endif
	#ifdef USE_SPECULAR_INTENSITYMAP
		uniform sampler2D specularIntensityMap;
	#endif
#endif
#ifdef USE_CLEARCOAT
	uniform float clearcoat;
	uniform float clearcoatRoughness;
#endif
#ifdef USE_DIFFUSE_ROUGHNESS
	uniform float diffuseRoughness;
	#ifdef USE_DIFFUSE_ROUGHNESSMAP
		uniform sampler2D diffuseRoughnessMap;
	#endif
#endif
#ifdef USE_DISPERSION
	uniform float dispersion;
#endif
#ifdef USE_RETROREFLECTION
	uniform float retroreflectivity;
#endif
#ifdef USE_IRIDESCENCE
	uniform float iridescence;
	uniform float iridescenceIOR;
	uniform float iridescenceThicknessMinimum;
	uniform float iridescenceThicknessMaximum;
#endif
#ifdef USE_SHEEN
	uniform vec3 sheenColor;
	uniform float sheenRoughness;
	#ifdef USE_SHEEN_COLORMAP
		uniform sampler2D sheenColorMap;
	#endif
	#ifdef USE_SHEEN_ROUGHNESSMAP
		uniform sampler2D sheenRoughnessMap;
	#endif
#endif
#ifdef USE_ANISOTROPY
	uniform vec2 anisotropyVector;
	#ifdef USE_ANISOTROPYMAP
		uniform sampler2D anisotropyMap;
	#endif
#endif
varying vec3 vViewPosition;
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <aomap_pars_fragment>
#include <lightmap_pars_fragment>
#include <emissivemap_pars_fragment>
#include <iridescence_fragment>
#include <envmap_common_pars_fragment>
#include <envmap_physical_pars_fragment>
#include <fog_pars_fragment>
#include <lights_pars_begin>
#include <normal_pars_fragment>
#include <lights_physical_pars_fragment>
#include <transmission_pars_fragment>
#include <shadowmap_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <clearcoat_pars_fragment>
#include <iridescence_pars_fragment>
#include <roughnessmap_pars_fragment>
#include <metalnessmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	ReflectedLight reflectedLight = ReflectedLight( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ) );
	vec3 totalEmissiveRadiance = emissive;
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <roughnessmap_fragment>
	#include <metalnessmap_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	#include <clearcoat_normal_fragment_begin>
	#include <clearcoat_normal_fragment_maps>
	#include <emissivemap_fragment>
	#include <lights_physical_fragment>
	#include <lights_fragment_begin>
	#include <lights_fragment_maps>
	#include <lights_fragment_end>
	#include <aomap_fragment>
	vec3 totalDiffuse = reflectedLight.directDiffuse + reflectedLight.indirectDiffuse;
	vec3 totalSpecular = reflectedLight.directSpecular + reflectedLight.indirectSpecular;
	#include <transmission_fragment>
	vec3 outgoingLight = totalDiffuse + totalSpecular + totalEmissiveRadiance;
	#ifdef USE_SHEEN
 
		outgoingLight = outgoingLight + sheenSpecularDirect + sheenSpecularIndirect;
 
 	#endif
	#ifdef USE_CLEARCOAT
		float dotNVcc = saturate( dot( geometryClearcoatNormal, geometryViewDir ) );
		vec3 Fcc = F_Schlick( material.clearcoatF0, material.clearcoatF90, dotNVcc );
		outgoingLight = outgoingLight * ( 1.0 - material.clearcoat * Fcc ) + ( clearcoatSpecularDirect + clearcoatSpecularIndirect ) * material.clearcoat;
	#endif
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,TI=`#define TOON
varying vec3 vViewPosition;
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <shadowmap_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	vViewPosition = - mvPosition.xyz;
	#include <worldpos_vertex>
	#include <shadowmap_vertex>
	#include <fog_vertex>
}`,AI=`#define TOON
uniform vec3 diffuse;
uniform vec3 emissive;
uniform float opacity;
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <aomap_pars_fragment>
#include <lightmap_pars_fragment>
#include <emissivemap_pars_fragment>
#include <gradientmap_pars_fragment>
#include <fog_pars_fragment>
#include <bsdfs>
#include <lights_pars_begin>
#include <normal_pars_fragment>
#include <lights_toon_pars_fragment>
#include <shadowmap_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	ReflectedLight reflectedLight = ReflectedLight( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ) );
	vec3 totalEmissiveRadiance = emissive;
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	#include <emissivemap_fragment>
	#include <lights_toon_fragment>
	#include <lights_fragment_begin>
	#include <lights_fragment_maps>
	#include <lights_fragment_end>
	#include <aomap_fragment>
	vec3 outgoingLight = reflectedLight.directDiffuse + reflectedLight.indirectDiffuse + totalEmissiveRadiance;
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,RI=`uniform float size;
uniform float scale;
#include <common>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <morphtarget_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
#ifdef USE_POINTS_UV
	varying vec2 vUv;
	uniform mat3 uvTransform;
#endif
void main() {
	#ifdef USE_POINTS_UV
		vUv = ( uvTransform * vec3( uv, 1 ) ).xy;
	#endif
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <project_vertex>
	gl_PointSize = size;
	#ifdef USE_SIZEATTENUATION
		bool isPerspective = isPerspectiveMatrix( projectionMatrix );
		if ( isPerspective ) gl_PointSize *= ( scale / - mvPosition.z );
	#endif
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	#include <worldpos_vertex>
	#include <fog_vertex>
}`,II=`uniform vec3 diffuse;
uniform float opacity;
#include <common>
#include <color_pars_fragment>
#include <map_particle_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <fog_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	vec3 outgoingLight = vec3( 0.0 );
	#include <logdepthbuf_fragment>
	#include <map_particle_fragment>
	#include <color_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	outgoingLight = diffuseColor.rgb;
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
}`,CI=`#include <common>
#include <batching_pars_vertex>
#include <fog_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <shadowmap_pars_vertex>
void main() {
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphinstance_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <worldpos_vertex>
	#include <shadowmap_vertex>
	#include <fog_vertex>
}`,NI=`uniform vec3 color;
uniform float opacity;
#include <common>
#include <fog_pars_fragment>
#include <bsdfs>
#include <lights_pars_begin>
#include <logdepthbuf_pars_fragment>
#include <shadowmap_pars_fragment>
#include <shadowmask_pars_fragment>
void main() {
	#include <logdepthbuf_fragment>
	gl_FragColor = vec4( color, opacity * ( 1.0 - getShadowMask() ) );
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
}`,PI=`uniform float rotation;
uniform vec2 center;
#include <common>
#include <uv_pars_vertex>
#include <fog_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	vec4 mvPosition = modelViewMatrix[ 3 ];
	vec2 scale = vec2( length( modelMatrix[ 0 ].xyz ), length( modelMatrix[ 1 ].xyz ) );
	#ifndef USE_SIZEATTENUATION
		bool isPerspective = isPerspectiveMatrix( projectionMatrix );
		if ( isPerspective ) scale *= - mvPosition.z;
	#endif
	vec2 alignedPosition = ( position.xy - ( center - vec2( 0.5 ) ) ) * scale;
	vec2 rotatedPosition;
	rotatedPosition.x = cos( rotation ) * alignedPosition.x - sin( rotation ) * alignedPosition.y;
	rotatedPosition.y = sin( rotation ) * alignedPosition.x + cos( rotation ) * alignedPosition.y;
	mvPosition.xy += rotatedPosition;
	gl_Position = projectionMatrix * mvPosition;
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	#include <fog_vertex>
}`,LI=`uniform vec3 diffuse;
uniform float opacity;
#include <common>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <fog_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	vec3 outgoingLight = vec3( 0.0 );
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	outgoingLight = diffuseColor.rgb;
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
}`,ht={alphahash_fragment:t1,alphahash_pars_fragment:n1,alphamap_fragment:i1,alphamap_pars_fragment:r1,alphatest_fragment:s1,alphatest_pars_fragment:o1,aomap_fragment:a1,aomap_pars_fragment:l1,batching_pars_vertex:c1,batching_vertex:u1,begin_vertex:h1,beginnormal_vertex:f1,bsdfs:d1,iridescence_fragment:p1,bumpmap_pars_fragment:m1,clipping_planes_fragment:g1,clipping_planes_pars_fragment:_1,clipping_planes_pars_vertex:y1,clipping_planes_vertex:x1,color_fragment:b1,color_pars_fragment:v1,color_pars_vertex:S1,color_vertex:E1,common:M1,defaultnormal_vertex:w1,displacementmap_pars_vertex:T1,displacementmap_vertex:A1,emissivemap_fragment:R1,emissivemap_pars_fragment:I1,colorspace_fragment:C1,colorspace_pars_fragment:N1,envmap_fragment:P1,envmap_common_pars_fragment:L1,envmap_pars_fragment:D1,envmap_pars_vertex:F1,envmap_physical_pars_fragment:Y1,envmap_vertex:U1,fog_vertex:O1,fog_pars_vertex:B1,fog_fragment:k1,fog_pars_fragment:V1,gradientmap_pars_fragment:G1,lightmap_pars_fragment:z1,lights_lambert_fragment:H1,lights_lambert_pars_fragment:W1,lights_pars_begin:X1,lights_toon_fragment:Z1,lights_toon_pars_fragment:K1,lights_phong_fragment:$1,lights_phong_pars_fragment:q1,lights_physical_fragment:J1,lights_physical_pars_fragment:j1,lights_fragment_begin:Q1,lights_fragment_maps:eR,lights_fragment_end:tR,lightprobes_pars_fragment:nR,logdepthbuf_fragment:iR,logdepthbuf_pars_fragment:rR,logdepthbuf_pars_vertex:sR,logdepthbuf_vertex:oR,map_fragment:aR,map_pars_fragment:lR,map_particle_fragment:cR,map_particle_pars_fragment:uR,metalnessmap_fragment:hR,metalnessmap_pars_fragment:fR,morphinstance_vertex:dR,morphcolor_vertex:pR,morphnormal_vertex:mR,morphtarget_pars_vertex:gR,morphtarget_vertex:_R,normal_fragment_begin:yR,normal_fragment_maps:xR,normal_pars_fragment:bR,normal_pars_vertex:vR,normal_vertex:SR,normalmap_pars_fragment:ER,clearcoat_normal_fragment_begin:MR,clearcoat_normal_fragment_maps:wR,clearcoat_pars_fragment:TR,iridescence_pars_fragment:AR,opaque_fragment:RR,packing:IR,premultiplied_alpha_fragment:CR,project_vertex:NR,dithering_fragment:PR,dithering_pars_fragment:LR,roughnessmap_fragment:DR,roughnessmap_pars_fragment:FR,shadowmap_pars_fragment:UR,shadowmap_pars_vertex:OR,shadowmap_vertex:BR,shadowmask_pars_fragment:kR,skinbase_vertex:VR,skinning_pars_vertex:GR,skinning_vertex:zR,skinnormal_vertex:HR,specularmap_fragment:WR,specularmap_pars_fragment:XR,tonemapping_fragment:YR,tonemapping_pars_fragment:ZR,transmission_fragment:KR,transmission_pars_fragment:$R,uv_pars_fragment:qR,uv_pars_vertex:JR,uv_vertex:jR,worldpos_vertex:QR,background_vert:eI,background_frag:tI,backgroundCube_vert:nI,backgroundCube_frag:iI,cube_vert:rI,cube_frag:sI,depth_vert:oI,depth_frag:aI,distance_vert:lI,distance_frag:cI,equirect_vert:uI,equirect_frag:hI,linedashed_vert:fI,linedashed_frag:dI,meshbasic_vert:pI,meshbasic_frag:mI,meshlambert_vert:gI,meshlambert_frag:_I,meshmatcap_vert:yI,meshmatcap_frag:xI,meshnormal_vert:bI,meshnormal_frag:vI,meshphong_vert:SI,meshphong_frag:EI,meshphysical_vert:MI,meshphysical_frag:wI,meshtoon_vert:TI,meshtoon_frag:AI,points_vert:RI,points_frag:II,shadow_vert:CI,shadow_frag:NI,sprite_vert:PI,sprite_frag:LI},Pe={common:{diffuse:{value:new tt(16777215)},opacity:{value:1},map:{value:null},mapTransform:{value:new it},alphaMap:{value:null},alphaMapTransform:{value:new it},alphaTest:{value:0}},specularmap:{specularMap:{value:null},specularMapTransform:{value:new it}},envmap:{envMap:{value:null},envMapRotation:{value:new it},reflectivity:{value:1},ior:{value:1.5},refractionRatio:{value:.98},dfgLUT:{value:null}},aomap:{aoMap:{value:null},aoMapIntensity:{value:1},aoMapTransform:{value:new it}},lightmap:{lightMap:{value:null},lightMapIntensity:{value:1},lightMapTransform:{value:new it}},bumpmap:{bumpMap:{value:null},bumpMapTransform:{value:new it},bumpScale:{value:1}},normalmap:{normalMap:{value:null},normalMapTransform:{value:new it},normalScale:{value:new Ke(1,1)}},displacementmap:{displacementMap:{value:null},displacementMapTransform:{value:new it},displacementScale:{value:1},displacementBias:{value:0}},emissivemap:{emissiveMap:{value:null},emissiveMapTransform:{value:new it}},metalnessmap:{metalnessMap:{value:null},metalnessMapTransform:{value:new it}},roughnessmap:{roughnessMap:{value:null},roughnessMapTransform:{value:new it}},gradientmap:{gradientMap:{value:null}},fog:{fogDensity:{value:25e-5},fogNear:{value:1},fogFar:{value:2e3},fogColor:{value:new tt(16777215)}},lights:{ambientLightColor:{value:[]},lightProbe:{value:[]},sunLights:{value:[],properties:{direction:{},color:{}}},sunLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{}}},sunShadowMatrix:{value:[]},sunShadowCascade:{value:[]},directionalLights:{value:[],properties:{direction:{},color:{}}},directionalLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{}}},directionalShadowMatrix:{value:[]},spotLights:{value:[],properties:{color:{},position:{},direction:{},distance:{},coneCos:{},penumbraCos:{},decay:{}}},spotLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{}}},spotLightMap:{value:[]},spotLightMatrix:{value:[]},pointLights:{value:[],properties:{color:{},position:{},decay:{},distance:{}}},pointLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{},shadowCameraNear:{},shadowCameraFar:{}}},pointShadowMatrix:{value:[]},hemisphereLights:{value:[],properties:{direction:{},skyColor:{},groundColor:{}}},rectAreaLights:{value:[],properties:{color:{},position:{},width:{},height:{}}},ltc_1:{value:null},ltc_2:{value:null},probesSH:{value:[]},probesMin:{value:[]},probesMax:{value:[]},probesResolution:{value:[]}},points:{diffuse:{value:new tt(16777215)},opacity:{value:1},size:{value:1},scale:{value:1},map:{value:null},alphaMap:{value:null},alphaMapTransform:{value:new it},alphaTest:{value:0},uvTransform:{value:new it}},sprite:{diffuse:{value:new tt(16777215)},opacity:{value:1},center:{value:new Ke(.5,.5)},rotation:{value:0},map:{value:null},mapTransform:{value:new it},alphaMap:{value:null},alphaMapTransform:{value:new it},alphaTest:{value:0}}},vr={basic:{uniforms:qn([Pe.common,Pe.specularmap,Pe.envmap,Pe.aomap,Pe.lightmap,Pe.fog]),vertexShader:ht.meshbasic_vert,fragmentShader:ht.meshbasic_frag},lambert:{uniforms:qn([Pe.common,Pe.specularmap,Pe.envmap,Pe.aomap,Pe.lightmap,Pe.emissivemap,Pe.bumpmap,Pe.normalmap,Pe.displacementmap,Pe.fog,Pe.lights,{emissive:{value:new tt(0)},envMapIntensity:{value:1}}]),vertexShader:ht.meshlambert_vert,fragmentShader:ht.meshlambert_frag},phong:{uniforms:qn([Pe.common,Pe.specularmap,Pe.envmap,Pe.aomap,Pe.lightmap,Pe.emissivemap,Pe.bumpmap,Pe.normalmap,Pe.displacementmap,Pe.fog,Pe.lights,{emissive:{value:new tt(0)},specular:{value:new tt(1118481)},shininess:{value:30},envMapIntensity:{value:1}}]),vertexShader:ht.meshphong_vert,fragmentShader:ht.meshphong_frag},standard:{uniforms:qn([Pe.common,Pe.envmap,Pe.aomap,Pe.lightmap,Pe.emissivemap,Pe.bumpmap,Pe.normalmap,Pe.displacementmap,Pe.roughnessmap,Pe.metalnessmap,Pe.fog,Pe.lights,{emissive:{value:new tt(0)},roughness:{value:1},metalness:{value:0},envMapIntensity:{value:1}}]),vertexShader:ht.meshphysical_vert,fragmentShader:ht.meshphysical_frag},toon:{uniforms:qn([Pe.common,Pe.aomap,Pe.lightmap,Pe.emissivemap,Pe.bumpmap,Pe.normalmap,Pe.displacementmap,Pe.gradientmap,Pe.fog,Pe.lights,{emissive:{value:new tt(0)}}]),vertexShader:ht.meshtoon_vert,fragmentShader:ht.meshtoon_frag},matcap:{uniforms:qn([Pe.common,Pe.bumpmap,Pe.normalmap,Pe.displacementmap,Pe.fog,{matcap:{value:null}}]),vertexShader:ht.meshmatcap_vert,fragmentShader:ht.meshmatcap_frag},points:{uniforms:qn([Pe.points,Pe.fog]),vertexShader:ht.points_vert,fragmentShader:ht.points_frag},dashed:{uniforms:qn([Pe.common,Pe.fog,{scale:{value:1},dashSize:{value:1},totalSize:{value:2}}]),vertexShader:ht.linedashed_vert,fragmentShader:ht.linedashed_frag},depth:{uniforms:qn([Pe.common,Pe.displacementmap]),vertexShader:ht.depth_vert,fragmentShader:ht.depth_frag},normal:{uniforms:qn([Pe.common,Pe.bumpmap,Pe.normalmap,Pe.displacementmap,{opacity:{value:1}}]),vertexShader:ht.meshnormal_vert,fragmentShader:ht.meshnormal_frag},sprite:{uniforms:qn([Pe.sprite,Pe.fog]),vertexShader:ht.sprite_vert,fragmentShader:ht.sprite_frag},background:{uniforms:{uvTransform:{value:new it},t2D:{value:null},backgroundIntensity:{value:1}},vertexShader:ht.background_vert,fragmentShader:ht.background_frag},backgroundCube:{uniforms:{envMap:{value:null},backgroundBlurriness:{value:0},backgroundIntensity:{value:1},backgroundRotation:{value:new it}},vertexShader:ht.backgroundCube_vert,fragmentShader:ht.backgroundCube_frag},cube:{uniforms:{tCube:{value:null},tFlip:{value:-1},opacity:{value:1}},vertexShader:ht.cube_vert,fragmentShader:ht.cube_frag},equirect:{uniforms:{tEquirect:{value:null}},vertexShader:ht.equirect_vert,fragmentShader:ht.equirect_frag},distance:{uniforms:qn([Pe.common,Pe.displacementmap,{referencePosition:{value:new X},nearDistance:{value:1},farDistance:{value:1e3}}]),vertexShader:ht.distance_vert,fragmentShader:ht.distance_frag},shadow:{uniforms:qn([Pe.lights,Pe.fog,{color:{value:new tt(0)},opacity:{value:1}}]),vertexShader:ht.shadow_vert,fragmentShader:ht.shadow_frag}};vr.physical={uniforms:qn([vr.standard.uniforms,{clearcoat:{value:0},clearcoatMap:{value:null},clearcoatMapTransform:{value:new it},clearcoatNormalMap:{value:null},clearcoatNormalMapTransform:{value:new it},clearcoatNormalScale:{value:new Ke(1,1)},clearcoatRoughness:{value:0},clearcoatRoughnessMap:{value:null},clearcoatRoughnessMapTransform:{value:new it},diffuseRoughness:{value:0},diffuseRoughnessMap:{value:null},diffuseRoughnessMapTransform:{value:new it},dispersion:{value:0},retroreflectivity:{value:0},iridescence:{value:0},iridescenceMap:{value:null},iridescenceMapTransform:{value:new it},iridescenceIOR:{value:1.3},iridescenceThicknessMinimum:{value:100},iridescenceThicknessMaximum:{value:400},iridescenceThicknessMap:{value:null},iridescenceThicknessMapTransform:{value:new it},sheen:{value:0},sheenColor:{value:new tt(0)},sheenColorMap:{value:null},sheenColorMapTransform:{value:new it},sheenRoughness:{value:1},sheenRoughnessMap:{value:null},sheenRoughnessMapTransform:{value:new it},transmission:{value:0},transmissionMap:{value:null},transmissionMapTransform:{value:new it},transmissionSamplerSize:{value:new Ke},transmissionSamplerMap:{value:null},thickness:{value:0},thicknessMap:{value:null},thicknessMapTransform:{value:new it},attenuationDistance:{value:0},attenuationColor:{value:new tt(0)},specularColor:{value:new tt(1,1,1)},specularColorMap:{value:null},specularColorMapTransform:{value:new it},specularIntensity:{value:1},specularIntensityMap:{value:null},specularIntensityMapTransform:{value:new it},anisotropyVector:{value:new Ke},anisotropyMap:{value:null},anisotropyMapTransform:{value:new it}}]),vertexShader:ht.meshphysical_vert,fragmentShader:ht.meshphysical_frag};var Zh={r:0,b:0,g:0},DI=new Tt,Sv=new it;Sv.set(-1,0,0,0,1,0,0,0,1);function FI(n,e,t,i,r,s){let o=new tt(0),a=r===!0?0:1,l,c,u=null,h=0,f=null;function d(b){let T=b.isScene===!0?b.background:null;if(T&&T.isTexture){let v=b.backgroundBlurriness>0;T=e.get(T,v)}return T}function p(b){let T=!1,v=d(b);v===null?m(o,a):v&&v.isColor&&(m(v,1),T=!0);let R=n.xr.getEnvironmentBlendMode();R==="additive"?t.buffers.color.setClear(0,0,0,1,s):R==="alpha-blend"&&t.buffers.color.setClear(0,0,0,0,s),(n.autoClear||T)&&(t.buffers.depth.setTest(!0),t.buffers.depth.setMask(!0),t.buffers.color.setMask(!0),n.clear(n.autoClearColor,n.autoClearDepth,n.autoClearStencil))}function x(b,T){let v=d(T);v&&v.isCubeTexture?(c===void 0&&(c=new Fi(new ds(1,1,1),new _r({name:"BackgroundCubeMaterial",uniforms:Xs(vr.backgroundCube.uniforms),vertexShader:vr.backgroundCube.vertexShader,fragmentShader:vr.backgroundCube.fragmentShader,side:si,depthTest:!1,depthWrite:!1,fog:!1,allowOverride:!1})),c.geometry.deleteAttribute("normal"),c.geometry.deleteAttribute("uv"),c.onBeforeRender=function(R,A,_){this.matrixWorld.copyPosition(_.matrixWorld)},Object.defineProperty(c.material,"envMap",{get:function(){return this.uniforms.envMap.value}}),i.update(c)),c.material.uniforms.envMap.value=v,c.material.uniforms.backgroundBlurriness.value=T.backgroundBlurriness,c.material.uniforms.backgroundIntensity.value=T.backgroundIntensity,c.material.uniforms.backgroundRotation.value.setFromMatrix4(DI.makeRotationFromEuler(T.backgroundRotation)).transpose(),v.isRenderTargetTexture===!1&&c.material.uniforms.backgroundRotation.value.premultiply(Sv),c.material.toneMapped=St.getTransfer(v.colorSpace)!==Lt,(u!==v||h!==v.version||f!==n.toneMapping)&&(c.material.needsUpdate=!0,u=v,h=v.version,f=n.toneMapping),c.layers.enableAll(),b.unshift(c,c.geometry,c.material,0,0,null)):v&&v.isTexture&&(l===void 0&&(l=new Fi(new gl(2,2),new _r({name:"BackgroundMaterial",uniforms:Xs(vr.background.uniforms),vertexShader:vr.background.vertexShader,fragmentShader:vr.background.fragmentShader,side:xs,depthTest:!1,depthWrite:!1,fog:!1,allowOverride:!1})),l.geometry.deleteAttribute("normal"),Object.defineProperty(l.material,"map",{get:function(){return this.uniforms.t2D.value}}),i.update(l)),l.material.uniforms.t2D.value=v,l.material.uniforms.backgroundIntensity.value=T.backgroundIntensity,l.material.toneMapped=St.getTransfer(v.colorSpace)!==Lt,v.matrixAutoUpdate===!0&&v.updateMatrix(),l.material.uniforms.uvTransform.value.copy(v.matrix),(u!==v||h!==v.version||f!==n.toneMapping)&&(l.material.needsUpdate=!0,u=v,h=v.version,f=n.toneMapping),l.layers.enableAll(),b.unshift(l,l.geometry,l.material,0,0,null))}function m(b,T){b.getRGB(Zh,dm(n)),t.buffers.color.setClear(Zh.r,Zh.g,Zh.b,T,s)}function g(){c!==void 0&&(c.geometry.dispose(),c.material.dispose(),c=void 0),l!==void 0&&(l.geometry.dispose(),l.material.dispose(),l=void 0)}return{getClearColor:function(){return o},setClearColor:function(b,T=1){o.set(b),a=T,m(o,a)},getClearAlpha:function(){return a},setClearAlpha:function(b){a=b,m(o,a)},render:p,addToRenderList:x,dispose:g}}function UI(n,e){let t=n.getParameter(n.MAX_VERTEX_ATTRIBS),i={},r=f(null),s=r,o=!1;function a(P,k,H,D,W){let K=!1,z=h(P,D,H,k);s!==z&&(s=z,c(s.object)),K=d(P,D,H,W),K&&p(P,D,H,W),W!==null&&e.update(W,n.ELEMENT_ARRAY_BUFFER),(K||o)&&(o=!1,v(P,k,H,D),W!==null&&n.bindBuffer(n.ELEMENT_ARRAY_BUFFER,e.get(W).buffer))}function l(){return n.createVertexArray()}function c(P){return n.bindVertexArray(P)}function u(P){return n.deleteVertexArray(P)}function h(P,k,H,D){let W=D.wireframe===!0,K=i[k.id];K===void 0&&(K={},i[k.id]=K);let z=P.isInstancedMesh===!0?P.id:0,ce=K[z];ce===void 0&&(ce={},K[z]=ce);let J=ce[H.id];J===void 0&&(J={},ce[H.id]=J);let Q=J[W];return Q===void 0&&(Q=f(l()),J[W]=Q),Q}function f(P){let k=[],H=[],D=[];for(let W=0;W<t;W++)k[W]=0,H[W]=0,D[W]=0;return{geometry:null,program:null,wireframe:!1,newAttributes:k,enabledAttributes:H,attributeDivisors:D,object:P,attributes:{},index:null}}function d(P,k,H,D){let W=s.attributes,K=k.attributes,z=0,ce=H.getAttributes();for(let J in ce)if(ce[J].location>=0){let re=W[J],fe=K[J];if(fe===void 0&&(J==="instanceMatrix"&&P.instanceMatrix&&(fe=P.instanceMatrix),J==="instanceColor"&&P.instanceColor&&(fe=P.instanceColor)),re===void 0||re.attribute!==fe||fe&&re.data!==fe.data)return!0;z++}return s.attributesNum!==z||s.index!==D}function p(P,k,H,D){let W={},K=k.attributes,z=0,ce=H.getAttributes();for(let J in ce)if(ce[J].location>=0){let re=K[J];re===void 0&&(J==="instanceMatrix"&&P.instanceMatrix&&(re=P.instanceMatrix),J==="instanceColor"&&P.instanceColor&&(re=P.instanceColor));let fe={};fe.attribute=re,re&&re.data&&(fe.data=re.data),W[J]=fe,z++}s.attributes=W,s.attributesNum=z,s.index=D}function x(){let P=s.newAttributes;for(let k=0,H=P.length;k<H;k++)P[k]=0}function m(P){g(P,0)}function g(P,k){let H=s.newAttributes,D=s.enabledAttributes,W=s.attributeDivisors;H[P]=1,D[P]===0&&(n.enableVertexAttribArray(P),D[P]=1),W[P]!==k&&(n.vertexAttribDivisor(P,k),W[P]=k)}function b(){let P=s.newAttributes,k=s.enabledAttributes;for(let H=0,D=k.length;H<D;H++)k[H]!==P[H]&&(n.disableVertexAttribArray(H),k[H]=0)}function T(P,k,H,D,W,K,z){z===!0?n.vertexAttribIPointer(P,k,H,W,K):n.vertexAttribPointer(P,k,H,D,W,K)}function v(P,k,H,D){x();let W=D.attributes,K=H.getAttributes(),z=k.defaultAttributeValues;for(let ce in K){let J=K[ce];if(J.location>=0){let Q=W[ce];if(Q===void 0&&(ce==="instanceMatrix"&&P.instanceMatrix&&(Q=P.instanceMatrix),ce==="instanceColor"&&P.instanceColor&&(Q=P.instanceColor)),Q!==void 0){let re=Q.normalized,fe=Q.itemSize,he=e.get(Q);if(he===void 0)continue;let ee=he.buffer,me=he.type,ye=he.bytesPerElement,Ae=me===n.INT||me===n.UNSIGNED_INT||Q.gpuType===ch;if(Q.isInterleavedBufferAttribute){let Se=Q.data,Xe=Se.isInterleavedBuffer===!0?Se.stride:Se.itemSize,ot=Q.offset;if(Se.isInstancedInterleavedBuffer||Se.isInstancedBufferAttribute){for(let ze=0;ze<J.locationSize;ze++)g(J.location+ze,Se.meshPerAttribute);P.isInstancedMesh!==!0&&D._maxInstanceCount===void 0&&(D._maxInstanceCount=Se.meshPerAttribute*Se.count)}else for(let ze=0;ze<J.locationSize;ze++)m(J.location+ze);n.bindBuffer(n.ARRAY_BUFFER,ee);for(let ze=0;ze<J.locationSize;ze++)T(J.location+ze,fe/J.locationSize,me,re,Xe*ye,(ot+fe/J.locationSize*ze)*ye,Ae)}else{if(Q.isInstancedBufferAttribute){for(let Se=0;Se<J.locationSize;Se++)g(J.location+Se,Q.meshPerAttribute);P.isInstancedMesh!==!0&&D._maxInstanceCount===void 0&&(D._maxInstanceCount=Q.meshPerAttribute*Q.count)}else for(let Se=0;Se<J.locationSize;Se++)m(J.location+Se);n.bindBuffer(n.ARRAY_BUFFER,ee);for(let Se=0;Se<J.locationSize;Se++)T(J.location+Se,fe/J.locationSize,me,re,fe*ye,fe/J.locationSize*Se*ye,Ae)}}else if(z!==void 0){let re=z[ce];if(re!==void 0)switch(re.length){case 2:n.vertexAttrib2fv(J.location,re);break;case 3:n.vertexAttrib3fv(J.location,re);break;case 4:n.vertexAttrib4fv(J.location,re);break;default:n.vertexAttrib1fv(J.location,re)}}}}b()}function R(){F();for(let P in i){let k=i[P];for(let H in k){let D=k[H];for(let W in D){let K=D[W];for(let z in K)u(K[z].object),delete K[z];delete D[W]}}delete i[P]}}function A(P){if(i[P.id]===void 0)return;let k=i[P.id];for(let H in k){let D=k[H];for(let W in D){let K=D[W];for(let z in K)u(K[z].object),delete K[z];delete D[W]}}delete i[P.id]}function _(P){for(let k in i){let H=i[k];for(let D in H){let W=H[D];if(W[P.id]===void 0)continue;let K=W[P.id];for(let z in K)u(K[z].object),delete K[z];delete W[P.id]}}}function E(P){for(let k in i){let H=i[k],D=P.isInstancedMesh===!0?P.id:0,W=H[D];if(W!==void 0){for(let K in W){let z=W[K];for(let ce in z)u(z[ce].object),delete z[ce];delete W[K]}delete H[D],Object.keys(H).length===0&&delete i[k]}}}function F(){N(),o=!0,s!==r&&(s=r,c(s.object))}function N(){r.geometry=null,r.program=null,r.wireframe=!1}return{setup:a,reset:F,resetDefaultState:N,dispose:R,releaseStatesOfGeometry:A,releaseStatesOfObject:E,releaseStatesOfProgram:_,initAttributes:x,enableAttribute:m,disableUnusedAttributes:b}}function OI(n,e,t){let i;function r(l){i=l}function s(l,c){n.drawArrays(i,l,c),t.update(c,i,1)}function o(l,c,u){u!==0&&(n.drawArraysInstanced(i,l,c,u),t.update(c,i,u))}function a(l,c,u){if(u===0)return;e.get("WEBGL_multi_draw").multiDrawArraysWEBGL(i,l,0,c,0,u);let f=0;for(let d=0;d<u;d++)f+=c[d];t.update(f,i,1)}this.setMode=r,this.render=s,this.renderInstances=o,this.renderMultiDraw=a}function BI(n,e,t,i){let r;function s(){if(r!==void 0)return r;if(e.has("EXT_texture_filter_anisotropic")===!0){let _=e.get("EXT_texture_filter_anisotropic");r=n.getParameter(_.MAX_TEXTURE_MAX_ANISOTROPY_EXT)}else r=0;return r}function o(_){return!(_!==er&&i.convert(_)!==n.getParameter(n.IMPLEMENTATION_COLOR_READ_FORMAT))}function a(_){let E=_===Qi&&(e.has("EXT_color_buffer_half_float")||e.has("EXT_color_buffer_float"));return!(_!==li&&_!==Ui&&!E&&i.convert(_)!==n.getParameter(n.IMPLEMENTATION_COLOR_READ_TYPE))}function l(_){if(_==="highp"){if(n.getShaderPrecisionFormat(n.VERTEX_SHADER,n.HIGH_FLOAT).precision>0&&n.getShaderPrecisionFormat(n.FRAGMENT_SHADER,n.HIGH_FLOAT).precision>0)return"highp";_="mediump"}return _==="mediump"&&n.getShaderPrecisionFormat(n.VERTEX_SHADER,n.MEDIUM_FLOAT).precision>0&&n.getShaderPrecisionFormat(n.FRAGMENT_SHADER,n.MEDIUM_FLOAT).precision>0?"mediump":"lowp"}let c=t.precision!==void 0?t.precision:"highp",u=l(c);u!==c&&($e("WebGLRenderer:",c,"not supported, using",u,"instead."),c=u);let h=t.reversedDepthBuffer===!0&&e.has("EXT_clip_control"),f=t.logarithmicDepthBuffer===!0&&h===!1;t.reversedDepthBuffer===!0&&h===!1&&$e("WebGLRenderer: Unable to use reversed depth buffer due to missing EXT_clip_control extension. Fallback to default depth buffer."),t.logarithmicDepthBuffer===!0&&h===!0&&$e("WebGLRenderer: Logarithmic depth buffer is ignored when reversed depth buffer is enabled.");let d=n.getParameter(n.MAX_TEXTURE_IMAGE_UNITS),p=n.getParameter(n.MAX_VERTEX_TEXTURE_IMAGE_UNITS),x=n.getParameter(n.MAX_TEXTURE_SIZE),m=n.getParameter(n.MAX_CUBE_MAP_TEXTURE_SIZE),g=n.getParameter(n.MAX_VERTEX_ATTRIBS),b=n.getParameter(n.MAX_VERTEX_UNIFORM_VECTORS),T=n.getParameter(n.MAX_VARYING_VECTORS),v=n.getParameter(n.MAX_FRAGMENT_UNIFORM_VECTORS),R=n.getParameter(n.MAX_SAMPLES),A=n.getParameter(n.SAMPLES);return{isWebGL2:!0,getMaxAnisotropy:s,getMaxPrecision:l,textureFormatReadable:o,textureTypeReadable:a,precision:c,logarithmicDepthBuffer:f,reversedDepthBuffer:h,maxTextures:d,maxVertexTextures:p,maxTextureSize:x,maxCubemapSize:m,maxAttributes:g,maxVertexUniforms:b,maxVaryings:T,maxFragmentUniforms:v,maxSamples:R,samples:A}}function kI(n){let e=this,t=null,i=0,r=!1,s=!1,o=new Ei,a=new it,l={value:null,needsUpdate:!1};this.uniform=l,this.numPlanes=0,this.numIntersection=0,this.init=function(h,f){let d=h.length!==0||f||i!==0||r;return r=f,i=h.length,d},this.beginShadows=function(){s=!0,u(null)},this.endShadows=function(){s=!1},this.setGlobalState=function(h,f){t=u(h,f,0)},this.setState=function(h,f,d){let p=h.clippingPlanes,x=h.clipIntersection,m=h.clipShadows,g=n.get(h);if(!r||p===null||p.length===0||s&&!m)s?u(null):c();else{let b=s?0:i,T=b*4,v=g.clippingState||null;l.value=v,v=u(p,f,T,d);for(let R=0;R!==T;++R)v[R]=t[R];g.clippingState=v,this.numIntersection=x?this.numPlanes:0,this.numPlanes+=b}};function c(){l.value!==t&&(l.value=t,l.needsUpdate=i>0),e.numPlanes=i,e.numIntersection=0}function u(h,f,d,p){let x=h!==null?h.length:0,m=null;if(x!==0){if(m=l.value,p!==!0||m===null){let g=d+x*4,b=f.matrixWorldInverse;a.getNormalMatrix(b),(m===null||m.length<g)&&(m=new Float32Array(g));for(let T=0,v=d;T!==x;++T,v+=4)o.copy(h[T]).applyMatrix4(b,a),o.normal.toArray(m,v),m[v+3]=o.constant}l.value=m,l.needsUpdate=!0}return e.numPlanes=x,e.numIntersection=0,m}}var Ul=class extends wi{constructor(e=1,t={}){super(e,e,t),this.isWebGLCubeRenderTarget=!0;let i={width:e,height:e,depth:1},r=[i,i,i,i,i,i];this.texture=new hl(r),this._setTextureOptions(t),this.texture.isRenderTargetTexture=!0}fromEquirectangularTexture(e,t){this.texture.type=t.type,this.texture.colorSpace=t.colorSpace,this.texture.generateMipmaps=t.generateMipmaps,this.texture.minFilter=t.minFilter,this.texture.magFilter=t.magFilter;let i={uniforms:{tEquirect:{value:null}},vertexShader:`

				varying vec3 vWorldDirection;

				vec3 transformDirection( in vec3 dir, in mat4 matrix ) {

					return normalize( ( matrix * vec4( dir, 0.0 ) ).xyz );

				}

				void main() {

					vWorldDirection = transformDirection( position, modelMatrix );

					#include <begin_vertex>
					#include <project_vertex>

				}
			`,fragmentShader:`

				uniform sampler2D tEquirect;

				varying vec3 vWorldDirection;

				#include <common>

				void main() {

					vec3 direction = normalize( vWorldDirection );

					vec2 sampleUV = equirectUv( direction );

					gl_FragColor = texture2D( tEquirect, sampleUV );

				}
			`},r=new ds(5,5,5),s=new _r({name:"CubemapFromEquirect",uniforms:Xs(i.uniforms),vertexShader:i.vertexShader,fragmentShader:i.fragmentShader,side:si,blending:Gs});s.uniforms.tEquirect.value=t;let o=new Fi(r,s),a=t.minFilter;return t.minFilter===Hr&&(t.minFilter=ri),new Jo(1,10,this).update(e,o),t.minFilter=a,o.geometry.dispose(),o.material.dispose(),this}clear(e,t=!0,i=!0,r=!0){let s=e.getRenderTarget();for(let o=0;o<6;o++)e.setRenderTarget(this,o),e.clear(t,i,r);e.setRenderTarget(s)}},ev=256,VI=3,GI=20,Ev=256,Mv=16,zI=3,HI=new X,WI=new tt,$h=class n{constructor(e){this._renderer=e,this._cubeSize=0,this._sourceTarget=null,this._cubeCamera=new Jo(1,10,null),this._boxMesh=new Fi(new ds(5,5,5),null),this._cubemapMaterial=null,this._equirectMaterial=null,this._blurMaterial=null,this._ggxMaterial=null,this._integrationMaterial=null}fromScene(e,t=0,i=.1,r=100,s={}){let{size:o=256,position:a=HI}=s,l=this._renderer;this._setSize(o);let c=this._allocateTarget(),u=this._getSourceTarget(!0);t>0&&(u.texture.mipmapsAutoUpdate=!1);let h=l.autoClear,f=l.autoClearColor,d=l.autoClearDepth,p=l.autoClearStencil,x=e.background;l.autoClear=!0,l.autoClearColor=!0,l.autoClearDepth=!0,l.autoClearStencil=!0,x===null&&(e.background=l.getClearColor(WI));let m=new Jo(i,r,u);return m.position.copy(a),m.update(l,e),l.autoClear=h,l.autoClearColor=f,l.autoClearDepth=d,l.autoClearStencil=p,e.background=x,t>0&&(u.texture.mipmapsAutoUpdate=!0,this._blur(c,t)),this._applyPMREM(c),c}fromEquirectangular(e,t=null){return this._fromTexture(e,t)}fromCubemap(e,t=null){return this._fromTexture(e,t)}compileCubemapShader(){this._cubemapMaterial===null&&(this._cubemapMaterial=iv(),this._compileMaterial(this._cubemapMaterial))}compileEquirectangularShader(){this._equirectMaterial===null&&(this._equirectMaterial=nv(),this._compileMaterial(this._equirectMaterial))}dispose(){this._sourceTarget!==null&&this._sourceTarget.dispose(),this._cubemapMaterial!==null&&this._cubemapMaterial.dispose(),this._equirectMaterial!==null&&this._equirectMaterial.dispose(),this._blurMaterial!==null&&this._blurMaterial.dispose(),this._ggxMaterial!==null&&this._ggxMaterial.dispose(),this._integrationMaterial!==null&&this._integrationMaterial.dispose(),this._boxMesh.geometry.dispose()}static lodToRoughness(e,t){return t>0?1-Math.sqrt(1-e/t):0}_setSize(e){this._cubeSize=Math.max(ev,hm(e))}_fromTexture(e,t){e.mapping===Hs||e.mapping===ta?this._setSize(e.image.length===0?ev:e.image[0].width||e.image[0].image.width):this._setSize(e.image.width/4);let i=t||this._allocateTarget();return this._textureToCubemap(e),this._applyPMREM(i),i}_allocateTarget(){let e=this._cubeSize,t=tv(e,!1,!1),i=Math.log2(e)-VI;for(let r=0;r<=i;r++)t.texture.mipmaps.push({width:e>>r,height:e>>r});return t.texture.name="PMREM",t.texture.isPMREMTexture=!0,t}_getSourceTarget(e=!1){let t=this._cubeSize,i=this._sourceTarget;return(i===null||i.width!==t||e&&i.depthBuffer===!1)&&(i!==null&&i.dispose(),this._sourceTarget=tv(t,!0,e)),this._sourceTarget}_compileMaterial(e){this._boxMesh.material=e,this._renderer.compile(this._boxMesh,this._cubeCamera.children[0])}_renderCube(e,t,i){let r=this._boxMesh,s=this._cubeCamera;r.material=i,s.renderTarget=e,s.activeMipmapLevel=t;let o=e.width>>t;e.viewport.set(0,0,o,o),s.update(this._renderer,r),e.viewport.set(0,0,e.width,e.height)}_textureToCubemap(e){let t;e.mapping===Hs||e.mapping===ta?(this._cubemapMaterial===null&&(this._cubemapMaterial=iv()),t=this._cubemapMaterial,t.uniforms.flipEnvMap.value=e.isRenderTargetTexture===!1?-1:1):(this._equirectMaterial===null&&(this._equirectMaterial=nv()),t=this._equirectMaterial),t.uniforms.envMap.value=e,this._renderCube(this._getSourceTarget(),0,t)}_applyPMREM(e){this._ggxMaterial===null&&(this._ggxMaterial=XI(),this._integrationMaterial=YI());let t=this._cubeSize,i=e.texture.mipmaps.length-1,r=this._ggxMaterial.uniforms;r.envMap.value=this._sourceTarget.texture;let s=this._integrationMaterial.uniforms;s.envMap.value=this._sourceTarget.texture,s.sourceLod.value=Math.log2(t/Mv);for(let o=0;o<=i;o++){let a=n.lodToRoughness(o,i);if(o>i-zI)s.roughness.value=a,this._renderCube(e,o,this._integrationMaterial);else{let l=a>0?Math.log2(t)+.5*Math.log2(6/(Ev*Math.pow(a,4)))+.5:0;r.roughness.value=a,r.lodBias.value=l,this._renderCube(e,o,this._ggxMaterial)}}}_blur(e,t){this._blurMaterial===null&&(this._blurMaterial=ZI());let i=this._blurMaterial,r=i.uniforms,s=this._sourceTarget;r.sigma.value=Math.min(t,Math.PI)/Math.SQRT2,r.envMap.value=s.texture,this._renderCube(e,0,i),r.envMap.value=e.texture,this._renderCube(s,0,i)}};function tv(n,e,t){return new Ul(n,{minFilter:Hr,generateMipmaps:e,type:Qi,colorSpace:nl,depthBuffer:t})}function Ol(n,e,t){return new _r({name:n,uniforms:e,vertexShader:ht.cube_vert,fragmentShader:t,side:si,blending:Gs,depthTest:!1,depthWrite:!1})}function XI(){return Ol("PMREMGGXConvolution",{envMap:{value:null},roughness:{value:0},lodBias:{value:0}},`

		#define GGX_SAMPLES ${Ev}u

		varying vec3 vWorldDirection;

		uniform samplerCube envMap;
		uniform float roughness;
		uniform float lodBias;

		#include <common>

		// Van der Corput radical inverse
		float radicalInverse_VdC( uint bits ) {

			bits = ( bits << 16u ) | ( bits >> 16u );
			bits = ( ( bits & 0x55555555u ) << 1u ) | ( ( bits & 0xAAAAAAAAu ) >> 1u );
			bits = ( ( bits & 0x33333333u ) << 2u ) | ( ( bits & 0xCCCCCCCCu ) >> 2u );
			bits = ( ( bits & 0x0F0F0F0Fu ) << 4u ) | ( ( bits & 0xF0F0F0F0u ) >> 4u );
			bits = ( ( bits & 0x00FF00FFu ) << 8u ) | ( ( bits & 0xFF00FF00u ) >> 8u );
			return float( bits ) * 2.3283064365386963e-10; // / 0x100000000

		}

		// Hammersley sequence
		vec2 hammersley( uint i, uint N ) {

			return vec2( float( i ) / float( N ), radicalInverse_VdC( i ) );

		}

		void main() {

			vec3 N = normalize( vWorldDirection );

			// For very low roughness, just sample the environment directly
			if ( roughness < 0.001 ) {

				gl_FragColor = vec4( textureLod( envMap, N, 0.0 ).rgb, 1.0 );
				return;

			}

			float alpha = roughness * roughness;
			float alpha2 = alpha * alpha;

			// Tangent space basis for VNDF sampling
			vec3 up = abs( N.z ) < 0.999 ? vec3( 0.0, 0.0, 1.0 ) : vec3( 1.0, 0.0, 0.0 );
			vec3 tangent = normalize( cross( up, N ) );
			vec3 bitangent = cross( N, tangent );

			vec3 prefilteredColor = vec3( 0.0 );
			float totalWeight = 0.0;

			for ( uint i = 0u; i < GGX_SAMPLES; i ++ ) {

				vec2 Xi = hammersley( i, GGX_SAMPLES );

				// With V = N, sample the reflected direction directly.
				float invQ = 1.0 / ( 1.0 - Xi.x + alpha2 * Xi.x );
				float NdotL = ( 1.0 - Xi.x - alpha2 * Xi.x ) * invQ;

				if ( NdotL > 0.0 ) {

					float phi = 2.0 * PI * Xi.y;
					float sinTheta = 2.0 * alpha * sqrt( Xi.x * ( 1.0 - Xi.x ) ) * invQ;
					vec3 L = N * NdotL + ( tangent * cos( phi ) + bitangent * sin( phi ) ) * sinTheta;

					// Match the source mip to the sample's solid angle. The terms
					// independent of the sample are precomputed in lodBias.
					float d = alpha2 * invQ;
					float lod = max( log2( d ) + lodBias, 0.0 );

					// Weight by NdotL for the split-sum approximation
					prefilteredColor += textureLod( envMap, L, lod ).rgb * NdotL;
					totalWeight += NdotL;

				}

			}

			gl_FragColor = vec4( prefilteredColor / totalWeight, 1.0 );

		}
	`)}function YI(){return Ol("PMREMGGXIntegration",{envMap:{value:null},roughness:{value:0},sourceLod:{value:0},sourceSize:{value:Mv}},`

		varying vec3 vWorldDirection;

		uniform samplerCube envMap;
		uniform float roughness;
		uniform float sourceLod;
		uniform int sourceSize;

		void main() {

			vec3 N = normalize( vWorldDirection );

			float alpha = roughness * roughness;
			float alpha2 = alpha * alpha;

			float texelSize = 2.0 / float( sourceSize );

			vec3 prefilteredColor = vec3( 0.0 );
			float totalWeight = 0.0;

			// Pair opposite texels: only the one in N's hemisphere contributes.
			for ( int face = 0; face < 3; face ++ ) {

				for ( int y = 0; y < sourceSize; y ++ ) {

					for ( int x = 0; x < sourceSize; x ++ ) {

						vec2 uv = ( vec2( x, y ) + 0.5 ) * texelSize - 1.0;
						vec3 texelDirection = face == 0 ? vec3( 1.0, uv ) : ( face == 1 ? vec3( uv.x, 1.0, uv.y ) : vec3( uv, 1.0 ) );

						float invDistance = inversesqrt( 1.0 + dot( uv, uv ) );
						float NdotL = dot( N, texelDirection );
						texelDirection *= NdotL < 0.0 ? - 1.0 : 1.0;
						NdotL = abs( NdotL ) * invDistance;

						// With V = N, NdotH squared is ( 1 + NdotL ) / 2. Common factors
						// in the GGX distribution and texel solid angle cancel when normalized.
						float d = 1.0 + alpha2 + ( alpha2 - 1.0 ) * NdotL;
						float weight = NdotL * invDistance * invDistance * invDistance / ( d * d );

						prefilteredColor += textureLod( envMap, texelDirection, sourceLod ).rgb * weight;
						totalWeight += weight;

					}

				}

			}

			gl_FragColor = vec4( prefilteredColor / totalWeight, 1.0 );

		}
	`)}function ZI(){return Ol("PMREMSphericalGaussianBlur",{envMap:{value:null},sigma:{value:0}},`

		#define SAMPLES ${GI}
		#define GOLDEN_ANGLE 2.39996322973

		varying vec3 vWorldDirection;

		uniform samplerCube envMap;
		uniform float sigma;

		#include <common>

		void main() {

			vec3 outputDirection = normalize( vWorldDirection );

			vec3 up = abs( outputDirection.z ) < 0.999 ? vec3( 0.0, 0.0, 1.0 ) : vec3( 1.0, 0.0, 0.0 );
			vec3 tangent = normalize( cross( up, outputDirection ) );
			vec3 bitangent = cross( outputDirection, tangent );

			// Truncate the kernel at three standard deviations or at the antipode.
			float thetaMax = min( 3.0 * sigma, PI );
			float truncation = 1.0 - exp( - 0.5 * thetaMax * thetaMax / ( sigma * sigma ) );

			vec3 accumColor = vec3( 0.0 );
			float accumWeight = 0.0;

			for ( int i = 0; i < SAMPLES; i ++ ) {

				// Stratified inverse-CDF sampling of the Gaussian, placed on a golden-angle spiral.
				float stratum = ( float( i ) + 0.5 ) / float( SAMPLES );
				float theta = sigma * sqrt( - 2.0 * log( 1.0 - stratum * truncation ) );
				float phi = float( i ) * GOLDEN_ANGLE;

				vec3 offset = cos( phi ) * tangent + sin( phi ) * bitangent;
				vec3 sampleDirection = cos( theta ) * outputDirection + sin( theta ) * offset;

				// Correct the planar sample density to solid angle.
				float weight = sin( theta ) / theta;

				accumColor += weight * textureLod( envMap, sampleDirection, 0.0 ).rgb;
				accumWeight += weight;

			}

			gl_FragColor = vec4( accumColor / accumWeight, 1.0 );

		}
	`)}function nv(){return Ol("PMREMEquirectangularToCubemap",{envMap:{value:null}},`

		varying vec3 vWorldDirection;

		uniform sampler2D envMap;

		#include <common>

		void main() {

			// Average four subpixel samples to preserve small, bright features.
			vec3 direction = normalize( vWorldDirection );
			vec3 dx = dFdx( direction ) * 0.25;
			vec3 dy = dFdy( direction ) * 0.25;

			vec3 color = textureLod( envMap, equirectUv( normalize( direction - dx - dy ) ), 0.0 ).rgb;
			color += textureLod( envMap, equirectUv( normalize( direction + dx - dy ) ), 0.0 ).rgb;
			color += textureLod( envMap, equirectUv( normalize( direction - dx + dy ) ), 0.0 ).rgb;
			color += textureLod( envMap, equirectUv( normalize( direction + dx + dy ) ), 0.0 ).rgb;
			gl_FragColor = vec4( color * 0.25, 1.0 );

		}
	`)}function iv(){return Ol("PMREMCubemapToCubemap",{envMap:{value:null},flipEnvMap:{value:-1}},`

		varying vec3 vWorldDirection;

		uniform samplerCube envMap;
		uniform float flipEnvMap;

		void main() {

			gl_FragColor = vec4( textureCube( envMap, vec3( flipEnvMap * vWorldDirection.x, vWorldDirection.yz ) ).rgb, 1.0 );

		}
	`)}function KI(n){let e=new WeakMap,t=new WeakMap,i=null;function r(f,d=!1){return f==null?null:d?o(f):s(f)}function s(f){if(f&&f.isTexture){let d=f.mapping;if(d===oh||d===ah)if(e.has(f)){let p=e.get(f).texture;return a(p,f.mapping)}else{let p=f.image;if(p&&p.height>0){let x=new Ul(p.height);return x.fromEquirectangularTexture(n,f),e.set(f,x),f.addEventListener("dispose",c),a(x.texture,f.mapping)}else return null}}return f}function o(f){if(f&&f.isTexture&&f.isPMREMTexture!==!0){let d=f.mapping,p=d===oh||d===ah,x=d===Hs||d===ta;if(p||x){let m=t.get(f),g=m!==void 0?m.texture.pmremVersion:0;if(f.isRenderTargetTexture&&f.pmremVersion!==g)return i===null&&(i=new $h(n)),m=p?i.fromEquirectangular(f,m):i.fromCubemap(f,m),m.texture.pmremVersion=f.pmremVersion,t.set(f,m),m.texture;if(m!==void 0)return m.texture;{let b=f.image;return p&&b&&b.height>0||x&&b&&l(b)?(i===null&&(i=new $h(n)),m=p?i.fromEquirectangular(f):i.fromCubemap(f),m.texture.pmremVersion=f.pmremVersion,t.set(f,m),f.addEventListener("dispose",u),m.texture):null}}}return f}function a(f,d){return d===oh?f.mapping=Hs:d===ah&&(f.mapping=ta),f}function l(f){let d=0,p=6;for(let x=0;x<p;x++)f[x]!==void 0&&d++;return d===p}function c(f){let d=f.target;d.removeEventListener("dispose",c);let p=e.get(d);p!==void 0&&(e.delete(d),p.dispose())}function u(f){let d=f.target;d.removeEventListener("dispose",u);let p=t.get(d);p!==void 0&&(t.delete(d),p.dispose())}function h(){e=new WeakMap,t=new WeakMap,i!==null&&(i.dispose(),i=null)}return{get:r,dispose:h}}function $I(n){let e={};function t(i){if(e[i]!==void 0)return e[i];let r=n.getExtension(i);return e[i]=r,r}return{has:function(i){return t(i)!==null},init:function(){t("EXT_color_buffer_float"),t("WEBGL_clip_cull_distance"),t("OES_texture_float_linear"),t("EXT_color_buffer_half_float"),t("WEBGL_multisampled_render_to_texture"),t("WEBGL_render_shared_exponent")},get:function(i){let r=t(i);return r===null&&Qa("WebGLRenderer: "+i+" extension not supported."),r}}}function qI(n,e,t,i){let r={},s=new WeakMap,o=new FinalizationRegistry(p=>delete r[p]);function a(p){l(p.target)}function l(p){p.index!==null&&e.remove(p.index);for(let m in p.attributes)e.remove(p.attributes[m]);p.removeEventListener("dispose",a),delete r[p.id],o.unregister(p);let x=s.get(p);x&&(e.remove(x),s.delete(p)),i.releaseStatesOfGeometry(p),p.isInstancedBufferGeometry===!0&&delete p._maxInstanceCount,t.memory.geometries--}function c(p,x){return r[x.id]!==void 0||(x.addEventListener("dispose",a),r[x.id]=new WeakRef(x),o.register(x,x.id,x),t.memory.geometries++),x}function u(p){let x=p.attributes;for(let m in x)e.update(x[m],n.ARRAY_BUFFER)}function h(p){let x=p.index,m=p.attributes.position,g=0;if(m===void 0)return;let b=x!==null?x.array.length:m.array.length/3-1,T=m.count>=65535?ll:al,v=new T(Math.ceil(b/3)*6,1),R=v.array;if(x!==null){let _=x.array;g=x.version;for(let E=0,F=0;E<b;E+=3){let N=_[E+0],P=_[E+1],k=_[E+2];R[F++]=N,R[F++]=P,R[F++]=P,R[F++]=k,R[F++]=k,R[F++]=N}}else{g=m.version;for(let _=0,E=0;_<b;_+=3){let F=_+0,N=_+1,P=_+2;R[E++]=F,R[E++]=N,R[E++]=N,R[E++]=P,R[E++]=P,R[E++]=F}}v.version=g;let A=s.get(p);A&&e.remove(A),s.set(p,v)}function f(p){let x=s.get(p);if(x){let m=p.index;m!==null&&x.version<m.version&&h(p)}else h(p);return s.get(p)}function d(){for(let p in r){let x=r[p].deref();x!==void 0&&l(x)}}return{get:c,update:u,getWireframeAttribute:f,dispose:d}}function JI(n,e,t){let i;function r(h){i=h}let s,o;function a(h){s=h.type,o=h.bytesPerElement}function l(h,f){n.drawElements(i,f,s,h*o),t.update(f,i,1)}function c(h,f,d){d!==0&&(n.drawElementsInstanced(i,f,s,h*o,d),t.update(f,i,d))}function u(h,f,d){if(d===0)return;e.get("WEBGL_multi_draw").multiDrawElementsWEBGL(i,f,0,s,h,0,d);let x=0;for(let m=0;m<d;m++)x+=f[m];t.update(x,i,1)}this.setMode=r,this.setIndex=a,this.render=l,this.renderInstances=c,this.renderMultiDraw=u}function jI(n){let e={geometries:0,textures:0},t={frame:0,calls:0,triangles:0,points:0,lines:0};function i(s,o,a){switch(t.calls++,o){case n.TRIANGLES:t.triangles+=a*(s/3);break;case n.LINES:t.lines+=a*(s/2);break;case n.LINE_STRIP:t.lines+=a*(s-1);break;case n.LINE_LOOP:t.lines+=a*s;break;case n.POINTS:t.points+=a*s;break;default:et("WebGLInfo: Unknown draw mode:",o);break}}function r(){t.calls=0,t.triangles=0,t.points=0,t.lines=0}return{memory:e,render:t,programs:null,autoReset:!0,reset:r,update:i}}function QI(n,e,t){let i=new WeakMap,r=new tn;function s(o,a,l){let c=o.morphTargetInfluences,u=a.morphAttributes.position||a.morphAttributes.normal||a.morphAttributes.color,h=u!==void 0?u.length:0,f=i.get(a);if(f===void 0||f.count!==h){let F=function(){_.dispose(),i.delete(a),a.removeEventListener("dispose",F)};f!==void 0&&f.texture.dispose();let d=a.morphAttributes.position!==void 0,p=a.morphAttributes.normal!==void 0,x=a.morphAttributes.color!==void 0,m=a.morphAttributes.position||[],g=a.morphAttributes.normal||[],b=a.morphAttributes.color||[],T=0;d===!0&&(T=1),p===!0&&(T=2),x===!0&&(T=3);let v=a.attributes.position.count*T,R=1;v>e.maxTextureSize&&(R=Math.ceil(v/e.maxTextureSize),v=e.maxTextureSize);let A=new Float32Array(v*R*4*h),_=new sl(A,v,R,h);_.type=Ui,_.needsUpdate=!0;let E=T*4;for(let N=0;N<h;N++){let P=m[N],k=g[N],H=b[N],D=v*R*4*N;for(let W=0;W<P.count;W++){let K=W*E;d===!0&&(r.fromBufferAttribute(P,W),A[D+K+0]=r.x,A[D+K+1]=r.y,A[D+K+2]=r.z,A[D+K+3]=0),p===!0&&(r.fromBufferAttribute(k,W),A[D+K+4]=r.x,A[D+K+5]=r.y,A[D+K+6]=r.z,A[D+K+7]=0),x===!0&&(r.fromBufferAttribute(H,W),A[D+K+8]=r.x,A[D+K+9]=r.y,A[D+K+10]=r.z,A[D+K+11]=H.itemSize===4?r.w:1)}}f={count:h,texture:_,size:new Ke(v,R)},i.set(a,f),a.addEventListener("dispose",F)}if(o.isInstancedMesh===!0&&o.morphTexture!==null)l.getUniforms().setValue(n,"morphTexture",o.morphTexture,t);else{let d=0;for(let x=0;x<c.length;x++)d+=c[x];let p=a.morphTargetsRelative?1:1-d;l.getUniforms().setValue(n,"morphTargetBaseInfluence",p),l.getUniforms().setValue(n,"morphTargetInfluences",c)}l.getUniforms().setValue(n,"morphTargetsTexture",f.texture,t),l.getUniforms().setValue(n,"morphTargetsTextureSize",f.size)}return{update:s}}function eC(n,e,t,i,r){let s=new WeakMap;function o(c){let u=r.render.frame,h=c.geometry,f=e.get(c,h);if(s.get(f)!==u&&(e.update(f),s.set(f,u)),c.isInstancedMesh&&(c.hasEventListener("dispose",l)===!1&&c.addEventListener("dispose",l),s.get(c)!==u&&(t.update(c.instanceMatrix,n.ARRAY_BUFFER),c.instanceColor!==null&&t.update(c.instanceColor,n.ARRAY_BUFFER),s.set(c,u))),c.isSkinnedMesh){let d=c.skeleton;s.get(d)!==u&&(d.update(),s.set(d,u))}return f}function a(){s=new WeakMap}function l(c){let u=c.target;u.removeEventListener("dispose",l),i.releaseStatesOfObject(u),t.remove(u.instanceMatrix),u.instanceColor!==null&&t.remove(u.instanceColor)}return{update:o,dispose:a}}var tC={[Xp]:"LINEAR_TONE_MAPPING",[Yp]:"REINHARD_TONE_MAPPING",[Zp]:"CINEON_TONE_MAPPING",[Kp]:"ACES_FILMIC_TONE_MAPPING",[qp]:"AGX_TONE_MAPPING",[Jp]:"NEUTRAL_TONE_MAPPING",[$p]:"CUSTOM_TONE_MAPPING"};function nC(n,e,t,i,r,s){let o=new wi(e,t,{type:n,depthBuffer:r,stencilBuffer:s,samples:i?4:0,storeMultisampledDepthBuffer:!1,storeMultisampledStencilBuffer:!1,resolveDepthBuffer:!1,resolveStencilBuffer:!1}),a=null,l=null,c=null,u=new Gn;u.setAttribute("position",new jt([-1,3,0,-1,-1,0,3,-1,0],3)),u.setAttribute("uv",new jt([0,2,0,0,2,0],2));let h=new Wu({uniforms:{tDiffuse:{value:null}},vertexShader:`
			precision highp float;

			uniform mat4 modelViewMatrix;
			uniform mat4 projectionMatrix;

			attribute vec3 position;
			attribute vec2 uv;

			varying vec2 vUv;

			void main() {
				vUv = uv;
				gl_Position = projectionMatrix * modelViewMatrix * vec4( position, 1.0 );
			}`,fragmentShader:`
			precision highp float;

			uniform sampler2D tDiffuse;

			varying vec2 vUv;

			#include <tonemapping_pars_fragment>
			#include <colorspace_pars_fragment>

			void main() {
				gl_FragColor = texture2D( tDiffuse, vUv );

				#ifdef LINEAR_TONE_MAPPING
					gl_FragColor.rgb = LinearToneMapping( gl_FragColor.rgb );
				#elif defined( REINHARD_TONE_MAPPING )
					gl_FragColor.rgb = ReinhardToneMapping( gl_FragColor.rgb );
				#elif defined( CINEON_TONE_MAPPING )
					gl_FragColor.rgb = CineonToneMapping( gl_FragColor.rgb );
				#elif defined( ACES_FILMIC_TONE_MAPPING )
					gl_FragColor.rgb = ACESFilmicToneMapping( gl_FragColor.rgb );
				#elif defined( AGX_TONE_MAPPING )
					gl_FragColor.rgb = AgXToneMapping( gl_FragColor.rgb );
				#elif defined( NEUTRAL_TONE_MAPPING )
					gl_FragColor.rgb = NeutralToneMapping( gl_FragColor.rgb );
				#elif defined( CUSTOM_TONE_MAPPING )
					gl_FragColor.rgb = CustomToneMapping( gl_FragColor.rgb );
				#endif

				#ifdef SRGB_TRANSFER
					gl_FragColor = sRGBTransferOETF( gl_FragColor );
				#endif
			}`,depthTest:!1,depthWrite:!1}),f=new Fi(u,h),d=new Sl(-1,1,1,-1,0,1),p=null,x=null,m=!1,g,b=null,T=[],v=!1;this.setSize=function(R,A){o.setSize(R,A),a!==null&&a.setSize(R,A),l!==null&&l.setSize(R,A);for(let _=0;_<T.length;_++){let E=T[_];E.setSize&&E.setSize(R,A)}},this.setEffects=function(R){T=R,v=T.length>0&&T[0].isRenderPass===!0;let A=o.width,_=o.height;T.length>0&&a===null&&(a=new wi(A,_,{type:Qi,depthBuffer:!1,stencilBuffer:!1}),l=new wi(A,_,{type:Qi,depthBuffer:!1,stencilBuffer:!1}));let E=r===!0&&T.some(F=>F.needsDepthTexture===!0);E!==(o.depthTexture!==null)&&(E===!0&&c===null&&(c=new zr(A,_),s===!0&&(c.format=Wr,c.type=Ws)),o.dispose(),o.depthTexture=E?c:null,o.resolveDepthBuffer=E,o.storeMultisampledDepthBuffer=E);for(let F=0;F<T.length;F++){let N=T[F];N.setSize&&N.setSize(A,_),E&&N.needsDepthTexture===!0&&N.setDepthTexture&&N.setDepthTexture(c)}},this.begin=function(R,A){if(m||R.toneMapping===xr&&T.length===0)return!1;if(b=A,A!==null){let _=A.width,E=A.height;(o.width!==_||o.height!==E)&&this.setSize(_,E)}return v===!1&&R.setRenderTarget(o),g=R.toneMapping,R.toneMapping=xr,!0},this.hasRenderPass=function(){return v},this.end=function(R,A){R.toneMapping=g,m=!0;let _=o,E=a;for(let F=0;F<T.length;F++){let N=T[F];N.enabled!==!1&&(N.render(R,E,_,A),N.needsSwap!==!1&&(_=E,E=E===a?l:a))}if(p!==R.outputColorSpace||x!==R.toneMapping){p=R.outputColorSpace,x=R.toneMapping,h.defines={},St.getTransfer(p)===Lt&&(h.defines.SRGB_TRANSFER="");let F=tC[x];F&&(h.defines[F]=""),h.needsUpdate=!0}h.uniforms.tDiffuse.value=_.texture,R.setRenderTarget(b),R.render(f,d),b=null,m=!1},this.isCompositing=function(){return m},this.dispose=function(){o.dispose(),a!==null&&a.dispose(),l!==null&&l.dispose(),u.dispose(),h.dispose()}}var wv=new ai,Tv=new zr(1,1),Av=new fl(1),Rv=new sl,Iv=new Uu,Cv=new hl,rv=[],sv=[],ov=new Float32Array(16),av=new Float32Array(9),lv=new Float32Array(4);function aa(n,e,t){let i=n[0];if(i<=0||i>0)return n;let r=e*t,s=rv[r];if(s===void 0&&(s=new Float32Array(r),rv[r]=s),e!==0){i.toArray(s,0);for(let o=1,a=0;o!==e;++o)a+=t,n[o].toArray(s,a)}return s}function In(n,e){if(n.length!==e.length)return!1;for(let t=0,i=n.length;t<i;t++)if(n[t]!==e[t])return!1;return!0}function Cn(n,e){for(let t=0,i=e.length;t<i;t++)n[t]=e[t]}function Jh(n,e){let t=sv[e];t===void 0&&(t=new Int32Array(e),sv[e]=t);for(let i=0;i!==e;++i)t[i]=n.allocateTextureUnit();return t}function iC(n,e){let t=this.cache;t[0]!==e&&(n.uniform1f(this.addr,e),t[0]=e)}function rC(n,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y)&&(n.uniform2f(this.addr,e.x,e.y),t[0]=e.x,t[1]=e.y);else{if(In(t,e))return;n.uniform2fv(this.addr,e),Cn(t,e)}}function sC(n,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z)&&(n.uniform3f(this.addr,e.x,e.y,e.z),t[0]=e.x,t[1]=e.y,t[2]=e.z);else if(e.r!==void 0)(t[0]!==e.r||t[1]!==e.g||t[2]!==e.b)&&(n.uniform3f(this.addr,e.r,e.g,e.b),t[0]=e.r,t[1]=e.g,t[2]=e.b);else{if(In(t,e))return;n.uniform3fv(this.addr,e),Cn(t,e)}}function oC(n,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z||t[3]!==e.w)&&(n.uniform4f(this.addr,e.x,e.y,e.z,e.w),t[0]=e.x,t[1]=e.y,t[2]=e.z,t[3]=e.w);else{if(In(t,e))return;n.uniform4fv(this.addr,e),Cn(t,e)}}function aC(n,e){let t=this.cache,i=e.elements;if(i===void 0){if(In(t,e))return;n.uniformMatrix2fv(this.addr,!1,e),Cn(t,e)}else{if(In(t,i))return;lv.set(i),n.uniformMatrix2fv(this.addr,!1,lv),Cn(t,i)}}function lC(n,e){let t=this.cache,i=e.elements;if(i===void 0){if(In(t,e))return;n.uniformMatrix3fv(this.addr,!1,e),Cn(t,e)}else{if(In(t,i))return;av.set(i),n.uniformMatrix3fv(this.addr,!1,av),Cn(t,i)}}function cC(n,e){let t=this.cache,i=e.elements;if(i===void 0){if(In(t,e))return;n.uniformMatrix4fv(this.addr,!1,e),Cn(t,e)}else{if(In(t,i))return;ov.set(i),n.uniformMatrix4fv(this.addr,!1,ov),Cn(t,i)}}function uC(n,e){let t=this.cache;t[0]!==e&&(n.uniform1i(this.addr,e),t[0]=e)}function hC(n,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y)&&(n.uniform2i(this.addr,e.x,e.y),t[0]=e.x,t[1]=e.y);else{if(In(t,e))return;n.uniform2iv(this.addr,e),Cn(t,e)}}function fC(n,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z)&&(n.uniform3i(this.addr,e.x,e.y,e.z),t[0]=e.x,t[1]=e.y,t[2]=e.z);else{if(In(t,e))return;n.uniform3iv(this.addr,e),Cn(t,e)}}function dC(n,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z||t[3]!==e.w)&&(n.uniform4i(this.addr,e.x,e.y,e.z,e.w),t[0]=e.x,t[1]=e.y,t[2]=e.z,t[3]=e.w);else{if(In(t,e))return;n.uniform4iv(this.addr,e),Cn(t,e)}}function pC(n,e){let t=this.cache;t[0]!==e&&(n.uniform1ui(this.addr,e),t[0]=e)}function mC(n,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y)&&(n.uniform2ui(this.addr,e.x,e.y),t[0]=e.x,t[1]=e.y);else{if(In(t,e))return;n.uniform2uiv(this.addr,e),Cn(t,e)}}function gC(n,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z)&&(n.uniform3ui(this.addr,e.x,e.y,e.z),t[0]=e.x,t[1]=e.y,t[2]=e.z);else{if(In(t,e))return;n.uniform3uiv(this.addr,e),Cn(t,e)}}function _C(n,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z||t[3]!==e.w)&&(n.uniform4ui(this.addr,e.x,e.y,e.z,e.w),t[0]=e.x,t[1]=e.y,t[2]=e.z,t[3]=e.w);else{if(In(t,e))return;n.uniform4uiv(this.addr,e),Cn(t,e)}}function jh(n){return n.version===0&&(n.compareFunction=am,n.needsUpdate=!0),n}function yC(n,e,t){let i=this.cache,r=t.allocateTextureUnit();i[0]!==r&&(n.uniform1i(this.addr,r),i[0]=r);let s;this.type===n.SAMPLER_2D_SHADOW?s=jh(Tv):s=wv,t.setTexture2D(e||s,r)}function xC(n,e,t){let i=this.cache,r=t.allocateTextureUnit();i[0]!==r&&(n.uniform1i(this.addr,r),i[0]=r),t.setTexture3D(e||Iv,r)}function bC(n,e,t){let i=this.cache,r=t.allocateTextureUnit();i[0]!==r&&(n.uniform1i(this.addr,r),i[0]=r);let s;this.type===n.SAMPLER_CUBE_SHADOW?s=jh(Av):s=Cv,t.setTextureCube(e||s,r)}function vC(n,e,t){let i=this.cache,r=t.allocateTextureUnit();i[0]!==r&&(n.uniform1i(this.addr,r),i[0]=r),t.setTexture2DArray(e||Rv,r)}function SC(n){switch(n){case 5126:return iC;case 35664:return rC;case 35665:return sC;case 35666:return oC;case 35674:return aC;case 35675:return lC;case 35676:return cC;case 5124:case 35670:return uC;case 35667:case 35671:return hC;case 35668:case 35672:return fC;case 35669:case 35673:return dC;case 5125:return pC;case 36294:return mC;case 36295:return gC;case 36296:return _C;case 35678:case 36198:case 36298:case 36306:case 35682:return yC;case 35679:case 36299:case 36307:return xC;case 35680:case 36300:case 36308:case 36293:return bC;case 36289:case 36303:case 36311:case 36292:return vC}}function EC(n,e){n.uniform1fv(this.addr,e)}function MC(n,e){let t=aa(e,this.size,2);n.uniform2fv(this.addr,t)}function wC(n,e){let t=aa(e,this.size,3);n.uniform3fv(this.addr,t)}function TC(n,e){let t=aa(e,this.size,4);n.uniform4fv(this.addr,t)}function AC(n,e){let t=aa(e,this.size,4);n.uniformMatrix2fv(this.addr,!1,t)}function RC(n,e){let t=aa(e,this.size,9);n.uniformMatrix3fv(this.addr,!1,t)}function IC(n,e){let t=aa(e,this.size,16);n.uniformMatrix4fv(this.addr,!1,t)}function CC(n,e){n.uniform1iv(this.addr,e)}function NC(n,e){n.uniform2iv(this.addr,e)}function PC(n,e){n.uniform3iv(this.addr,e)}function LC(n,e){n.uniform4iv(this.addr,e)}function DC(n,e){n.uniform1uiv(this.addr,e)}function FC(n,e){n.uniform2uiv(this.addr,e)}function UC(n,e){n.uniform3uiv(this.addr,e)}function OC(n,e){n.uniform4uiv(this.addr,e)}function BC(n,e,t){let i=this.cache,r=e.length,s=Jh(t,r);In(i,s)||(n.uniform1iv(this.addr,s),Cn(i,s));let o;this.type===n.SAMPLER_2D_SHADOW?o=jh(Tv):o=wv;for(let a=0;a!==r;++a)t.setTexture2D(e[a]||o,s[a])}function kC(n,e,t){let i=this.cache,r=e.length,s=Jh(t,r);In(i,s)||(n.uniform1iv(this.addr,s),Cn(i,s));for(let o=0;o!==r;++o)t.setTexture3D(e[o]||Iv,s[o])}function VC(n,e,t){let i=this.cache,r=e.length,s=Jh(t,r);In(i,s)||(n.uniform1iv(this.addr,s),Cn(i,s));let o;this.type===n.SAMPLER_CUBE_SHADOW?o=jh(Av):o=Cv;for(let a=0;a!==r;++a)t.setTextureCube(e[a]||o,s[a])}function GC(n,e,t){let i=this.cache,r=e.length,s=Jh(t,r);In(i,s)||(n.uniform1iv(this.addr,s),Cn(i,s));for(let o=0;o!==r;++o)t.setTexture2DArray(e[o]||Rv,s[o])}function zC(n){switch(n){case 5126:return EC;case 35664:return MC;case 35665:return wC;case 35666:return TC;case 35674:return AC;case 35675:return RC;case 35676:return IC;case 5124:case 35670:return CC;case 35667:case 35671:return NC;case 35668:case 35672:return PC;case 35669:case 35673:return LC;case 5125:return DC;case 36294:return FC;case 36295:return UC;case 36296:return OC;case 35678:case 36198:case 36298:case 36306:case 35682:return BC;case 35679:case 36299:case 36307:return kC;case 35680:case 36300:case 36308:case 36293:return VC;case 36289:case 36303:case 36311:case 36292:return GC}}var xm=class{constructor(e,t,i){this.id=e,this.addr=i,this.cache=[],this.type=t.type,this.setValue=SC(t.type)}},bm=class{constructor(e,t,i){this.id=e,this.addr=i,this.cache=[],this.type=t.type,this.size=t.size,this.setValue=zC(t.type)}},vm=class{constructor(e){this.id=e,this.seq=[],this.map={}}setValue(e,t,i){let r=this.seq;for(let s=0,o=r.length;s!==o;++s){let a=r[s];a.setValue(e,t[a.id],i)}}},_m=/(\w+)(\])?(\[|\.)?/g;function cv(n,e){n.seq.push(e),n.map[e.id]=e}function HC(n,e,t){let i=n.name,r=i.length;for(_m.lastIndex=0;;){let s=_m.exec(i),o=_m.lastIndex,a=s[1],l=s[2]==="]",c=s[3];if(l&&(a=a|0),c===void 0||c==="["&&o+2===r){cv(t,c===void 0?new xm(a,n,e):new bm(a,n,e));break}else{let h=t.map[a];h===void 0&&(h=new vm(a),cv(t,h)),t=h}}}var oa=class{constructor(e,t){this.seq=[],this.map={};let i=e.getProgramParameter(t,e.ACTIVE_UNIFORMS);for(let o=0;o<i;++o){let a=e.getActiveUniform(t,o),l=e.getUniformLocation(t,a.name);HC(a,l,this)}let r=[],s=[];for(let o of this.seq)o.type===e.SAMPLER_2D_SHADOW||o.type===e.SAMPLER_CUBE_SHADOW||o.type===e.SAMPLER_2D_ARRAY_SHADOW?r.push(o):s.push(o);r.length>0&&(this.seq=r.concat(s))}setValue(e,t,i,r){let s=this.map[t];s!==void 0&&s.setValue(e,i,r)}setOptional(e,t,i){let r=t[i];r!==void 0&&this.setValue(e,i,r)}static upload(e,t,i,r){for(let s=0,o=t.length;s!==o;++s){let a=t[s],l=i[a.id];l.needsUpdate!==!1&&a.setValue(e,l.value,r)}}static seqWithValue(e,t){let i=[];for(let r=0,s=e.length;r!==s;++r){let o=e[r];o.id in t&&i.push(o)}return i}};function uv(n,e,t){let i=n.createShader(e);return n.shaderSource(i,t),n.compileShader(i),i}var WC=37297,XC=0;function YC(n,e){let t=n.split(`
`),i=[],r=Math.max(e-6,0),s=Math.min(e+6,t.length);for(let o=r;o<s;o++){let a=o+1;i.push(`${a===e?">":" "} ${a}: ${t[o]}`)}return i.join(`
`)}var hv=new it;function ZC(n){St._getMatrix(hv,St.workingColorSpace,n);let e=`mat3( ${hv.elements.map(t=>t.toFixed(4))} )`;switch(St.getTransfer(n)){case il:return[e,"LinearTransferOETF"];case Lt:return[e,"sRGBTransferOETF"];default:return $e("WebGLProgram: Unsupported color space: ",n),[e,"LinearTransferOETF"]}}function fv(n,e,t){let i=n.getShaderParameter(e,n.COMPILE_STATUS),s=(n.getShaderInfoLog(e)||"").trim();if(i&&s==="")return"";let o=/ERROR: 0:(\d+)/.exec(s);if(o){let a=parseInt(o[1]);return t.toUpperCase()+`

`+s+`

`+YC(n.getShaderSource(e),a)}else return s}function KC(n,e){let t=ZC(e);return[`vec4 ${n}( vec4 value ) {`,`	return ${t[1]}( vec4( ${t[0]} * value.rgb, value.a ) );`,"}"].join(`
`)}var $C={[Xp]:"Linear",[Yp]:"Reinhard",[Zp]:"Cineon",[Kp]:"ACESFilmic",[qp]:"AgX",[Jp]:"Neutral",[$p]:"Custom"};function qC(n,e){let t=$C[e];return t===void 0?($e("WebGLProgram: Unsupported toneMapping:",e),"vec3 "+n+"( vec3 color ) { return LinearToneMapping( color ); }"):"vec3 "+n+"( vec3 color ) { return "+t+"ToneMapping( color ); }"}var Kh=new X;function JC(){St.getLuminanceCoefficients(Kh);let n=Kh.x.toFixed(4),e=Kh.y.toFixed(4),t=Kh.z.toFixed(4);return["float luminance( const in vec3 rgb ) {",`	const vec3 weights = vec3( ${n}, ${e}, ${t} );`,"	return dot( weights, rgb );","}"].join(`
`)}function jC(n){return[n.extensionClipCullDistance?"#extension GL_ANGLE_clip_cull_distance : require":"",n.extensionMultiDraw?"#extension GL_ANGLE_multi_draw : require":""].filter(Fl).join(`
`)}function QC(n){let e=[];for(let t in n){let i=n[t];i!==!1&&e.push("#define "+t+" "+i)}return e.join(`
`)}function eN(n,e){let t={},i=n.getProgramParameter(e,n.ACTIVE_ATTRIBUTES);for(let r=0;r<i;r++){let s=n.getActiveAttrib(e,r),o=s.name,a=1;s.type===n.FLOAT_MAT2&&(a=2),s.type===n.FLOAT_MAT3&&(a=3),s.type===n.FLOAT_MAT4&&(a=4),t[o]={type:s.type,location:n.getAttribLocation(e,o),locationSize:a}}return t}function Fl(n){return n!==""}function dv(n,e){let t=e.numSpotLightShadows+e.numSpotLightMaps-e.numSpotLightShadowsWithMaps;return n.replace(/NUM_SUN_LIGHTS/g,e.numSunLights).replace(/NUM_DIR_LIGHTS/g,e.numDirLights).replace(/NUM_SPOT_LIGHTS/g,e.numSpotLights).replace(/NUM_SPOT_LIGHT_MAPS/g,e.numSpotLightMaps).replace(/NUM_SPOT_LIGHT_COORDS/g,t).replace(/NUM_RECT_AREA_LIGHTS/g,e.numRectAreaLights).replace(/NUM_POINT_LIGHTS/g,e.numPointLights).replace(/NUM_HEMI_LIGHTS/g,e.numHemiLights).replace(/NUM_SUN_LIGHT_SHADOWS/g,e.numSunLightShadows).replace(/NUM_DIR_LIGHT_SHADOWS/g,e.numDirLightShadows).replace(/NUM_SPOT_LIGHT_SHADOWS_WITH_MAPS/g,e.numSpotLightShadowsWithMaps).replace(/NUM_SPOT_LIGHT_SHADOWS/g,e.numSpotLightShadows).replace(/NUM_POINT_LIGHT_SHADOWS/g,e.numPointLightShadows).replace(/NUM_LIGHT_PROBE_GRIDS/g,e.numLightProbeGrids)}function pv(n,e){return n.replace(/NUM_CLIPPING_PLANES/g,e.numClippingPlanes).replace(/UNION_CLIPPING_PLANES/g,e.numClippingPlanes-e.numClipIntersection)}var tN=/^[ \t]*#include +<([\w\d./]+)>/gm;function Sm(n){return n.replace(tN,nN)}function nN(n,e){let t=ht[e];if(t===void 0)throw new Error("THREE.WebGLProgram: Can not resolve #include <"+e+">");return Sm(t)}var iN=/#pragma unroll_loop_start\s+for\s*\(\s*int\s+i\s*=\s*(\d+)\s*;\s*i\s*<\s*(\d+)\s*;\s*i\s*\+\+\s*\)\s*{([\s\S]+?)}\s+#pragma unroll_loop_end/g;function mv(n){return n.replace(iN,rN)}function rN(n,e,t,i){let r="";for(let s=parseInt(e);s<parseInt(t);s++)r+=i.replace(/\[\s*i\s*\]/g,"[ "+s+" ]").replace(/UNROLLED_LOOP_INDEX/g,s);return r}function gv(n){let e=`precision ${n.precision} float;
	precision ${n.precision} int;
	precision ${n.precision} sampler2D;
	precision ${n.precision} samplerCube;
	precision ${n.precision} sampler3D;
	precision ${n.precision} sampler2DArray;
	precision ${n.precision} sampler2DShadow;
	precision ${n.precision} samplerCubeShadow;
	precision ${n.precision} sampler2DArrayShadow;
	precision ${n.precision} isampler2D;
	precision ${n.precision} isampler3D;
	precision ${n.precision} isamplerCube;
	precision ${n.precision} isampler2DArray;
	precision ${n.precision} usampler2D;
	precision ${n.precision} usampler3D;
	precision ${n.precision} usamplerCube;
	precision ${n.precision} usampler2DArray;
	`;return n.precision==="highp"?e+=`
#define HIGH_PRECISION`:n.precision==="mediump"?e+=`
#define MEDIUM_PRECISION`:n.precision==="lowp"&&(e+=`
#define LOW_PRECISION`),e}var sN={[Tl]:"SHADOWMAP_TYPE_PCF",[Qo]:"SHADOWMAP_TYPE_VSM"};function oN(n){return sN[n.shadowMapType]||"SHADOWMAP_TYPE_BASIC"}var aN={[ta]:"ENVMAP_MODE_REFRACTION"};function lN(n){return n.envMap===!1?"ENVMAP_MODE_REFLECTION":aN[n.envMapMode]||"ENVMAP_MODE_REFLECTION"}var cN={[sh]:"ENVMAP_BLENDING_MULTIPLY",[Pb]:"ENVMAP_BLENDING_MIX",[Lb]:"ENVMAP_BLENDING_ADD"};function uN(n){return n.envMap===!1?"ENVMAP_BLENDING_NONE":cN[n.combine]||"ENVMAP_BLENDING_NONE"}function hN(n,e,t,i){let r=n.getContext(),s=t.defines,o=t.vertexShader,a=t.fragmentShader,l=oN(t),c=t.envMapPMREM===!0?"ENVMAP_TYPE_PMREM":"ENVMAP_TYPE_CUBE",u=lN(t),h=uN(t),f=jC(t),d=QC(s),p=r.createProgram(),x,m,g=t.glslVersion?"#version "+t.glslVersion+`
`:"";t.isRawShaderMaterial?(x=["#define SHADER_TYPE "+t.shaderType,"#define SHADER_NAME "+t.shaderName,d].filter(Fl).join(`
`),x.length>0&&(x+=`
`),m=["#define SHADER_TYPE "+t.shaderType,"#define SHADER_NAME "+t.shaderName,d].filter(Fl).join(`
`),m.length>0&&(m+=`
`)):(x=[gv(t),"#define SHADER_TYPE "+t.shaderType,"#define SHADER_NAME "+t.shaderName,d,t.extensionClipCullDistance?"#define USE_CLIP_DISTANCE":"",t.batching?"#define USE_BATCHING":"",t.batchingColor?"#define USE_BATCHING_COLOR":"",t.instancing?"#define USE_INSTANCING":"",t.instancingColor?"#define USE_INSTANCING_COLOR":"",t.instancingMorph?"#define USE_INSTANCING_MORPH":"",t.useFog&&t.fog?"#define USE_FOG":"",t.useFog&&t.fogExp2?"#define FOG_EXP2":"",t.map?"#define USE_MAP":"",t.envMap?"#define USE_ENVMAP":"",t.envMap?"#define "+u:"",t.lightMap?"#define USE_LIGHTMAP":"",t.aoMap?"#define USE_AOMAP":"",t.bumpMap?"#define USE_BUMPMAP":"",t.normalMap?"#define USE_NORMALMAP":"",t.normalMapObjectSpace?"#define USE_NORMALMAP_OBJECTSPACE":"",t.normalMapTangentSpace?"#define USE_NORMALMAP_TANGENTSPACE":"",t.displacementMap?"#define USE_DISPLACEMENTMAP":"",t.emissiveMap?"#define USE_EMISSIVEMAP":"",t.anisotropy?"#define USE_ANISOTROPY":"",t.anisotropyMap?"#define USE_ANISOTROPYMAP":"",t.clearcoatMap?"#define USE_CLEARCOATMAP":"",t.clearcoatRoughnessMap?"#define USE_CLEARCOAT_ROUGHNESSMAP":"",t.clearcoatNormalMap?"#define USE_CLEARCOAT_NORMALMAP":"",t.diffuseRoughnessMap?"#define USE_DIFFUSE_ROUGHNESSMAP":"",t.iridescenceMap?"#define USE_IRIDESCENCEMAP":"",t.iridescenceThicknessMap?"#define USE_IRIDESCENCE_THICKNESSMAP":"",t.specularMap?"#define USE_SPECULARMAP":"",t.specularColorMap?"#define USE_SPECULAR_COLORMAP":"",t.specularIntensityMap?"#define USE_SPECULAR_INTENSITYMAP":"",t.roughnessMap?"#define USE_ROUGHNESSMAP":"",t.metalnessMap?"#define USE_METALNESSMAP":"",t.alphaMap?"#define USE_ALPHAMAP":"",t.alphaHash?"#define USE_ALPHAHASH":"",t.transmission?"#define USE_TRANSMISSION":"",t.transmissionMap?"#define USE_TRANSMISSIONMAP":"",t.thicknessMap?"#define USE_THICKNESSMAP":"",t.sheenColorMap?"#define USE_SHEEN_COLORMAP":"",t.sheenRoughnessMap?"#define USE_SHEEN_ROUGHNESSMAP":"",t.mapUv?"#define MAP_UV "+t.mapUv:"",t.alphaMapUv?"#define ALPHAMAP_UV "+t.alphaMapUv:"",t.lightMapUv?"#define LIGHTMAP_UV "+t.lightMapUv:"",t.aoMapUv?"#define AOMAP_UV "+t.aoMapUv:"",t.emissiveMapUv?"#define EMISSIVEMAP_UV "+t.emissiveMapUv:"",t.bumpMapUv?"#define BUMPMAP_UV "+t.bumpMapUv:"",t.normalMapUv?"#define NORMALMAP_UV "+t.normalMapUv:"",t.displacementMapUv?"#define DISPLACEMENTMAP_UV "+t.displacementMapUv:"",t.metalnessMapUv?"#define METALNESSMAP_UV "+t.metalnessMapUv:"",t.roughnessMapUv?"#define ROUGHNESSMAP_UV "+t.roughnessMapUv:"",t.anisotropyMapUv?"#define ANISOTROPYMAP_UV "+t.anisotropyMapUv:"",t.clearcoatMapUv?"#define CLEARCOATMAP_UV "+t.clearcoatMapUv:"",t.clearcoatNormalMapUv?"#define CLEARCOAT_NORMALMAP_UV "+t.clearcoatNormalMapUv:"",t.clearcoatRoughnessMapUv?"#define CLEARCOAT_ROUGHNESSMAP_UV "+t.clearcoatRoughnessMapUv:"",t.diffuseRoughnessMapUv?"#define DIFFUSE_ROUGHNESSMAP_UV "+t.diffuseRoughnessMapUv:"",t.iridescenceMapUv?"#define IRIDESCENCEMAP_UV "+t.iridescenceMapUv:"",t.iridescenceThicknessMapUv?"#define IRIDESCENCE_THICKNESSMAP_UV "+t.iridescenceThicknessMapUv:"",t.sheenColorMapUv?"#define SHEEN_COLORMAP_UV "+t.sheenColorMapUv:"",t.sheenRoughnessMapUv?"#define SHEEN_ROUGHNESSMAP_UV "+t.sheenRoughnessMapUv:"",t.specularMapUv?"#define SPECULARMAP_UV "+t.specularMapUv:"",t.specularColorMapUv?"#define SPECULAR_COLORMAP_UV "+t.specularColorMapUv:"",t.specularIntensityMapUv?"#define SPECULAR_INTENSITYMAP_UV "+t.specularIntensityMapUv:"",t.transmissionMapUv?"#define TRANSMISSIONMAP_UV "+t.transmissionMapUv:"",t.thicknessMapUv?"#define THICKNESSMAP_UV "+t.thicknessMapUv:"",t.vertexTangents&&t.flatShading===!1?"#define USE_TANGENT":"",t.vertexNormals?"#define HAS_NORMAL":"",t.vertexColors?"#define USE_COLOR":"",t.vertexAlphas?"#define USE_COLOR_ALPHA":"",t.vertexUv1s?"#define USE_UV1":"",t.vertexUv2s?"#define USE_UV2":"",t.vertexUv3s?"#define USE_UV3":"",t.pointsUvs?"#define USE_POINTS_UV":"",t.flatShading?"#define FLAT_SHADED":"",t.skinning?"#define USE_SKINNING":"",t.morphTargets?"#define USE_MORPHTARGETS":"",t.morphNormals&&t.flatShading===!1?"#define USE_MORPHNORMALS":"",t.morphColors?"#define USE_MORPHCOLORS":"",t.morphTargetsCount>0?"#define MORPHTARGETS_TEXTURE_STRIDE "+t.morphTextureStride:"",t.morphTargetsCount>0?"#define MORPHTARGETS_COUNT "+t.morphTargetsCount:"",t.doubleSided?"#define DOUBLE_SIDED":"",t.flipSided?"#define FLIP_SIDED":"",t.shadowMapEnabled?"#define USE_SHADOWMAP":"",t.shadowMapEnabled?"#define "+l:"",t.sizeAttenuation?"#define USE_SIZEATTENUATION":"",t.numLightProbes>0?"#define USE_LIGHT_PROBES":"",t.logarithmicDepthBuffer?"#define USE_LOGARITHMIC_DEPTH_BUFFER":"",t.reversedDepthBuffer?"#define USE_REVERSED_DEPTH_BUFFER":"","uniform mat4 modelMatrix;","uniform mat4 modelViewMatrix;","uniform mat4 projectionMatrix;","uniform mat4 viewMatrix;","uniform mat3 normalMatrix;","uniform vec3 cameraPosition;","uniform bool isOrthographic;","#ifdef USE_INSTANCING","	attribute mat4 instanceMatrix;","#endif","#ifdef USE_INSTANCING_COLOR","	attribute vec3 instanceColor;","#endif","#ifdef USE_INSTANCING_MORPH","	uniform sampler2D morphTexture;","#endif","attribute vec3 position;","attribute vec3 normal;","attribute vec2 uv;","#ifdef USE_UV1","	attribute vec2 uv1;","#endif","#ifdef USE_UV2","	attribute vec2 uv2;","#endif","#ifdef USE_UV3","	attribute vec2 uv3;","#endif","#ifdef USE_TANGENT","	attribute vec4 tangent;","#endif","#if defined( USE_COLOR_ALPHA )","	attribute vec4 color;","#elif defined( USE_COLOR )","	attribute vec3 color;","#endif","#ifdef USE_SKINNING","	attribute vec4 skinIndex;","	attribute vec4 skinWeight;","#endif",`
`].filter(Fl).join(`
`),m=[gv(t),"#define SHADER_TYPE "+t.shaderType,"#define SHADER_NAME "+t.shaderName,d,t.useFog&&t.fog?"#define USE_FOG":"",t.useFog&&t.fogExp2?"#define FOG_EXP2":"",t.alphaToCoverage?"#define ALPHA_TO_COVERAGE":"",t.map?"#define USE_MAP":"",t.matcap?"#define USE_MATCAP":"",t.envMap?"#define USE_ENVMAP":"",t.envMap?"#define "+c:"",t.envMap?"#define "+u:"",t.envMap?"#define "+h:"",t.envMapPMREM?"#define ENVMAP_MAX_LOD "+t.envMapMaxLod+".0":"",t.envMapPMREM?"#define ENVMAP_SIZE "+t.envMapSize+".0":"",t.lightMap?"#define USE_LIGHTMAP":"",t.aoMap?"#define USE_AOMAP":"",t.bumpMap?"#define USE_BUMPMAP":"",t.normalMap?"#define USE_NORMALMAP":"",t.normalMapObjectSpace?"#define USE_NORMALMAP_OBJECTSPACE":"",t.normalMapTangentSpace?"#define USE_NORMALMAP_TANGENTSPACE":"",t.packedNormalMap?"#define USE_PACKED_NORMALMAP":"",t.emissiveMap?"#define USE_EMISSIVEMAP":"",t.anisotropy?"#define USE_ANISOTROPY":"",t.anisotropyMap?"#define USE_ANISOTROPYMAP":"",t.clearcoat?"#define USE_CLEARCOAT":"",t.clearcoatMap?"#define USE_CLEARCOATMAP":"",t.clearcoatRoughnessMap?"#define USE_CLEARCOAT_ROUGHNESSMAP":"",t.clearcoatNormalMap?"#define USE_CLEARCOAT_NORMALMAP":"",t.diffuseRoughness?"#define USE_DIFFUSE_ROUGHNESS":"",t.diffuseRoughnessMap?"#define USE_DIFFUSE_ROUGHNESSMAP":"",t.dispersion?"#define USE_DISPERSION":"",t.retroreflection?"#define USE_RETROREFLECTION":"",t.iridescence?"#define USE_IRIDESCENCE":"",t.iridescenceMap?"#define USE_IRIDESCENCEMAP":"",t.iridescenceThicknessMap?"#define USE_IRIDESCENCE_THICKNESSMAP":"",t.specularMap?"#define USE_SPECULARMAP":"",t.specularColorMap?"#define USE_SPECULAR_COLORMAP":"",t.specularIntensityMap?"#define USE_SPECULAR_INTENSITYMAP":"",t.roughnessMap?"#define USE_ROUGHNESSMAP":"",t.metalnessMap?"#define USE_METALNESSMAP":"",t.alphaMap?"#define USE_ALPHAMAP":"",t.alphaTest?"#define USE_ALPHATEST":"",t.alphaHash?"#define USE_ALPHAHASH":"",t.sheen?"#define USE_SHEEN":"",t.sheenColorMap?"#define USE_SHEEN_COLORMAP":"",t.sheenRoughnessMap?"#define USE_SHEEN_ROUGHNESSMAP":"",t.transmission?"#define USE_TRANSMISSION":"",t.transmissionMap?"#define USE_TRANSMISSIONMAP":"",t.thicknessMap?"#define USE_THICKNESSMAP":"",t.vertexTangents&&t.flatShading===!1?"#define USE_TANGENT":"",t.vertexColors||t.instancingColor?"#define USE_COLOR":"",t.vertexAlphas||t.batchingColor?"#define USE_COLOR_ALPHA":"",t.vertexUv1s?"#define USE_UV1":"",t.vertexUv2s?"#define USE_UV2":"",t.vertexUv3s?"#define USE_UV3":"",t.pointsUvs?"#define USE_POINTS_UV":"",t.gradientMap?"#define USE_GRADIENTMAP":"",t.flatShading?"#define FLAT_SHADED":"",t.doubleSided?"#define DOUBLE_SIDED":"",t.flipSided?"#define FLIP_SIDED":"",t.shadowMapEnabled?"#define USE_SHADOWMAP":"",t.shadowMapEnabled?"#define "+l:"",t.premultipliedAlpha?"#define PREMULTIPLIED_ALPHA":"",t.numLightProbes>0?"#define USE_LIGHT_PROBES":"",t.decodeVideoTexture?"#define DECODE_VIDEO_TEXTURE":"",t.decodeVideoTextureEmissive?"#define DECODE_VIDEO_TEXTURE_EMISSIVE":"",t.logarithmicDepthBuffer?"#define USE_LOGARITHMIC_DEPTH_BUFFER":"",t.reversedDepthBuffer?"#define USE_REVERSED_DEPTH_BUFFER":"","uniform mat4 viewMatrix;","uniform vec3 cameraPosition;","uniform bool isOrthographic;",t.toneMapping!==xr?"#define TONE_MAPPING":"",t.toneMapping!==xr?ht.tonemapping_pars_fragment:"",t.toneMapping!==xr?qC("toneMapping",t.toneMapping):"",t.dithering?"#define DITHERING":"",t.opaque?"#define OPAQUE":"",ht.colorspace_pars_fragment,KC("linearToOutputTexel",t.outputColorSpace),JC(),t.useDepthPacking?"#define DEPTH_PACKING "+t.depthPacking:"",`
`].filter(Fl).join(`
`)),o=Sm(o),o=dv(o,t),o=pv(o,t),a=Sm(a),a=dv(a,t),a=pv(a,t),o=mv(o),a=mv(a),t.isRawShaderMaterial!==!0&&(g=`#version 300 es
`,x=[f,"#define attribute in","#define varying out","#define texture2D texture"].join(`
`)+`
`+x,m=["#define varying in",t.glslVersion===lm?"":"layout(location = 0) out highp vec4 pc_fragColor;",t.glslVersion===lm?"":"#define gl_FragColor pc_fragColor","#define gl_FragDepthEXT gl_FragDepth","#define texture2D texture","#define textureCube texture","#define texture2DProj textureProj","#define texture2DLodEXT textureLod","#define texture2DProjLodEXT textureProjLod","#define textureCubeLodEXT textureLod","#define texture2DGradEXT textureGrad","#define texture2DProjGradEXT textureProjGrad","#define textureCubeGradEXT textureGrad"].join(`
`)+`
`+m);let b=g+x+o,T=g+m+a,v=uv(r,r.VERTEX_SHADER,b),R=uv(r,r.FRAGMENT_SHADER,T);r.attachShader(p,v),r.attachShader(p,R),t.index0AttributeName!==void 0?r.bindAttribLocation(p,0,t.index0AttributeName):t.hasPositionAttribute===!0&&r.bindAttribLocation(p,0,"position"),r.linkProgram(p);function A(N){if(n.debug.checkShaderErrors){let P=r.getProgramInfoLog(p)||"",k=r.getShaderInfoLog(v)||"",H=r.getShaderInfoLog(R)||"",D=P.trim(),W=k.trim(),K=H.trim(),z=!0,ce=!0;if(r.getProgramParameter(p,r.LINK_STATUS)===!1)if(z=!1,typeof n.debug.onShaderError=="function")n.debug.onShaderError(r,p,v,R);else{let J=fv(r,v,"vertex"),Q=fv(r,R,"fragment");et("WebGLProgram: Shader Error "+r.getError()+" - VALIDATE_STATUS "+r.getProgramParameter(p,r.VALIDATE_STATUS)+`

Material Name: `+N.name+`
Material Type: `+N.type+`

Program Info Log: `+D+`
`+J+`
`+Q)}else D!==""?$e("WebGLProgram: Program Info Log:",D):(W===""||K==="")&&(ce=!1);ce&&(N.diagnostics={runnable:z,programLog:D,vertexShader:{log:W,prefix:x},fragmentShader:{log:K,prefix:m}})}r.deleteShader(v),r.deleteShader(R),_=new oa(r,p),E=eN(r,p)}let _;this.getUniforms=function(){return _===void 0&&A(this),_};let E;this.getAttributes=function(){return E===void 0&&A(this),E};let F=t.rendererExtensionParallelShaderCompile===!1;return this.isReady=function(){return F===!1&&(F=r.getProgramParameter(p,WC)),F},this.destroy=function(){i.releaseStatesOfProgram(this),r.deleteProgram(p),this.program=void 0},this.type=t.shaderType,this.name=t.shaderName,this.id=XC++,this.cacheKey=e,this.usedTimes=1,this.program=p,this.vertexShader=v,this.fragmentShader=R,this}var fN=0,Em=class{constructor(){this.shaderCache=new Map,this.materialCache=new Map}update(e,t,i){let r=this._getShaderCacheForMaterial(e);return r.has(t)===!1&&(r.add(t),t.usedTimes++),r.has(i)===!1&&(r.add(i),i.usedTimes++),this}remove(e){let t=this.materialCache.get(e);for(let i of t)i.usedTimes--,i.usedTimes===0&&this.shaderCache.delete(i.code);return this.materialCache.delete(e),this}getVertexShaderStage(e){return this._getShaderStage(e.vertexShader)}getFragmentShaderStage(e){return this._getShaderStage(e.fragmentShader)}dispose(){this.shaderCache.clear(),this.materialCache.clear()}_getShaderCacheForMaterial(e){let t=this.materialCache,i=t.get(e);return i===void 0&&(i=new Set,t.set(e,i)),i}_getShaderStage(e){let t=this.shaderCache,i=t.get(e);return i===void 0&&(i=new Mm(e),t.set(e,i)),i}},Mm=class{constructor(e){this.id=fN++,this.code=e,this.usedTimes=0}};function dN(n){return n===bs||n===Pl||n===Ll}function pN(n,e,t,i,r,s){let o=new Zo,a=new Em,l=new Set,c=[],u=new Map,h=i.logarithmicDepthBuffer,f={MeshDepthMaterial:"depth",MeshDistanceMaterial:"distance",MeshNormalMaterial:"normal",MeshBasicMaterial:"basic",MeshLambertMaterial:"lambert",MeshPhongMaterial:"phong",MeshToonMaterial:"toon",MeshStandardMaterial:"physical",MeshPhysicalMaterial:"physical",MeshMatcapMaterial:"matcap",LineBasicMaterial:"basic",LineDashedMaterial:"dashed",PointsMaterial:"points",ShadowMaterial:"shadow",SpriteMaterial:"sprite"};function d(_){return l.add(_),_===0?"uv":`uv${_}`}function p(_,E,F,N,P,k){let H=N.fog,D=P.geometry,W=_.isMeshStandardMaterial||_.isMeshLambertMaterial||_.isMeshPhongMaterial?N.environment:null,K=_.isMeshStandardMaterial||_.isMeshLambertMaterial&&!_.envMap||_.isMeshPhongMaterial&&!_.envMap,z=e.get(_.envMap||W,K),ce=f[_.type],J=i.precision;_.precision!==null&&(J=i.getMaxPrecision(_.precision),J!==_.precision&&$e("WebGLProgram.getParameters:",_.precision,"not supported, using",J,"instead."));let Q=D.morphAttributes.position||D.morphAttributes.normal||D.morphAttributes.color,re=Q!==void 0?Q.length:0,fe=0;D.morphAttributes.position!==void 0&&(fe=1),D.morphAttributes.normal!==void 0&&(fe=2),D.morphAttributes.color!==void 0&&(fe=3);let he,ee,me,ye;if(ce){let Re=vr[ce];he=Re.vertexShader,ee=Re.fragmentShader}else{he=_.vertexShader,ee=_.fragmentShader;let Re=a.getVertexShaderStage(_),lt=a.getFragmentShaderStage(_);a.update(_,Re,lt),me=Re.id,ye=lt.id}let Ae=n.getRenderTarget(),Se=n.state.buffers.depth.getReversed(),Xe=P.isInstancedMesh===!0,ot=P.isBatchedMesh===!0,ze=!!_.map,ft=!!_.matcap,ct=!!z,rt=ct&&z.isPMREMTexture===!0,Qt=!!_.aoMap,Xt=!!_.lightMap,mn=!!_.bumpMap&&_.wireframe===!1,Ot=!!_.normalMap,Ln=!!_.displacementMap,wt=!!_.emissiveMap,Mn=!!_.metalnessMap,sn=!!_.roughnessMap,gn=_.anisotropy>0,O=_.clearcoat>0,Ie=_.diffuseRoughness>0,qe=_.dispersion>0,at=_.retroreflectivity>0,Ee=_.iridescence>0,Vt=_.sheen>0,Ge=_.transmission>0,Ze=gn&&!!_.anisotropyMap,I=O&&!!_.clearcoatMap,S=O&&!!_.clearcoatNormalMap,Y=O&&!!_.clearcoatRoughnessMap,ue=Ie&&!!_.diffuseRoughnessMap,oe=Ee&&!!_.iridescenceMap,_e=Ee&&!!_.iridescenceThicknessMap,xe=Vt&&!!_.sheenColorMap,te=Vt&&!!_.sheenRoughnessMap,ie=!!_.specularMap,pe=!!_.specularColorMap,U=!!_.specularIntensityMap,se=Ge&&!!_.transmissionMap,ne=Ge&&!!_.thicknessMap,Me=!!_.gradientMap,ge=!!_.alphaMap,ve=_.alphaTest>0,He=!!_.alphaHash,je=!!_.extensions,le=xr;_.toneMapped&&(Ae===null||Ae.isXRRenderTarget===!0)&&(le=n.toneMapping);let Be=rt?z.isCompressedCubeTexture?z.image[0].mipmaps:z.mipmaps:null,Qe={shaderID:ce,shaderType:_.type,shaderName:_.name,vertexShader:he,fragmentShader:ee,defines:_.defines,customVertexShaderID:me,customFragmentShaderID:ye,isRawShaderMaterial:_.isRawShaderMaterial===!0,glslVersion:_.glslVersion,precision:J,batching:ot,batchingColor:ot&&P._colorsTexture!==null,instancing:Xe,instancingColor:Xe&&P.instanceColor!==null,instancingMorph:Xe&&P.morphTexture!==null,outputColorSpace:Ae===null?n.outputColorSpace:Ae.isXRRenderTarget===!0?Ae.texture.colorSpace:St.workingColorSpace,alphaToCoverage:!!_.alphaToCoverage,map:ze,matcap:ft,envMap:ct,envMapMode:ct&&z.mapping,envMapPMREM:rt,envMapMaxLod:rt?Be.length-1:null,envMapSize:rt?Be[0].width:null,aoMap:Qt,lightMap:Xt,bumpMap:mn,normalMap:Ot,displacementMap:Ln,emissiveMap:wt,normalMapObjectSpace:Ot&&_.normalMapType===Ub,normalMapTangentSpace:Ot&&_.normalMapType===Yh,packedNormalMap:Ot&&_.normalMapType===Yh&&dN(_.normalMap.format),metalnessMap:Mn,roughnessMap:sn,anisotropy:gn,anisotropyMap:Ze,clearcoat:O,clearcoatMap:I,clearcoatNormalMap:S,clearcoatRoughnessMap:Y,diffuseRoughness:Ie,diffuseRoughnessMap:ue,dispersion:qe,retroreflection:at,iridescence:Ee,iridescenceMap:oe,iridescenceThicknessMap:_e,sheen:Vt,sheenColorMap:xe,sheenRoughnessMap:te,specularMap:ie,specularColorMap:pe,specularIntensityMap:U,transmission:Ge,transmissionMap:se,thicknessMap:ne,gradientMap:Me,opaque:_.transparent===!1&&_.blending===ea&&_.alphaToCoverage===!1,alphaMap:ge,alphaTest:ve,alphaHash:He,combine:_.combine,mapUv:ze&&d(_.map.channel),aoMapUv:Qt&&d(_.aoMap.channel),lightMapUv:Xt&&d(_.lightMap.channel),bumpMapUv:mn&&d(_.bumpMap.channel),normalMapUv:Ot&&d(_.normalMap.channel),displacementMapUv:Ln&&d(_.displacementMap.channel),emissiveMapUv:wt&&d(_.emissiveMap.channel),metalnessMapUv:Mn&&d(_.metalnessMap.channel),roughnessMapUv:sn&&d(_.roughnessMap.channel),anisotropyMapUv:Ze&&d(_.anisotropyMap.channel),clearcoatMapUv:I&&d(_.clearcoatMap.channel),clearcoatNormalMapUv:S&&d(_.clearcoatNormalMap.channel),clearcoatRoughnessMapUv:Y&&d(_.clearcoatRoughnessMap.channel),diffuseRoughnessMapUv:ue&&d(_.diffuseRoughnessMap.channel),iridescenceMapUv:oe&&d(_.iridescenceMap.channel),iridescenceThicknessMapUv:_e&&d(_.iridescenceThicknessMap.channel),sheenColorMapUv:xe&&d(_.sheenColorMap.channel),sheenRoughnessMapUv:te&&d(_.sheenRoughnessMap.channel),specularMapUv:ie&&d(_.specularMap.channel),specularColorMapUv:pe&&d(_.specularColorMap.channel),specularIntensityMapUv:U&&d(_.specularIntensityMap.channel),transmissionMapUv:se&&d(_.transmissionMap.channel),thicknessMapUv:ne&&d(_.thicknessMap.channel),alphaMapUv:ge&&d(_.alphaMap.channel),vertexTangents:!!D.attributes.tangent&&(Ot||gn),vertexNormals:!!D.attributes.normal,vertexColors:_.vertexColors,vertexAlphas:_.vertexColors===!0&&!!D.attributes.color&&D.attributes.color.itemSize===4,pointsUvs:P.isPoints===!0&&!!D.attributes.uv&&(ze||ge),fog:!!H,useFog:_.fog===!0,fogExp2:!!H&&H.isFogExp2,flatShading:_.wireframe===!1&&(_.flatShading===!0||D.attributes.normal===void 0&&Ot===!1&&(_.isMeshLambertMaterial||_.isMeshPhongMaterial||_.isMeshStandardMaterial||_.isMeshPhysicalMaterial)),sizeAttenuation:_.sizeAttenuation===!0,logarithmicDepthBuffer:h,reversedDepthBuffer:Se,skinning:P.isSkinnedMesh===!0,hasPositionAttribute:D.attributes.position!==void 0,morphTargets:D.morphAttributes.position!==void 0,morphNormals:D.morphAttributes.normal!==void 0,morphColors:D.morphAttributes.color!==void 0,morphTargetsCount:re,morphTextureStride:fe,numSunLights:E.sun.length,numDirLights:E.directional.length,numPointLights:E.point.length,numSpotLights:E.spot.length,numSpotLightMaps:E.spotLightMap.length,numRectAreaLights:E.rectArea.length,numHemiLights:E.hemi.length,numSunLightShadows:E.sunShadowMap.length,numDirLightShadows:E.directionalShadowMap.length,numPointLightShadows:E.pointShadowMap.length,numSpotLightShadows:E.spotShadowMap.length,numSpotLightShadowsWithMaps:E.numSpotLightShadowsWithMaps,numLightProbes:E.numLightProbes,numLightProbeGrids:k.filter(Re=>Re.texture!==null).length,numClippingPlanes:s.numPlanes,numClipIntersection:s.numIntersection,dithering:_.dithering,shadowMapEnabled:n.shadowMap.enabled&&F.length>0,shadowMapType:n.shadowMap.type,toneMapping:le,decodeVideoTexture:ze&&_.map.isVideoTexture===!0&&St.getTransfer(_.map.colorSpace)===Lt,decodeVideoTextureEmissive:wt&&_.emissiveMap.isVideoTexture===!0&&St.getTransfer(_.emissiveMap.colorSpace)===Lt,premultipliedAlpha:_.premultipliedAlpha,doubleSided:_.side===yr,flipSided:_.side===si,useDepthPacking:_.depthPacking>=0,depthPacking:_.depthPacking||0,index0AttributeName:_.index0AttributeName,extensionClipCullDistance:je&&_.extensions.clipCullDistance===!0&&t.has("WEBGL_clip_cull_distance"),extensionMultiDraw:(je&&_.extensions.multiDraw===!0||ot)&&t.has("WEBGL_multi_draw"),rendererExtensionParallelShaderCompile:t.has("KHR_parallel_shader_compile"),customProgramCacheKey:_.customProgramCacheKey()};return Qe.vertexUv1s=l.has(1),Qe.vertexUv2s=l.has(2),Qe.vertexUv3s=l.has(3),l.clear(),Qe}function x(_){let E=[];if(_.shaderID?E.push(_.shaderID):(E.push(_.customVertexShaderID),E.push(_.customFragmentShaderID)),_.defines!==void 0)for(let F in _.defines)E.push(F),E.push(_.defines[F]);return _.isRawShaderMaterial===!1&&(m(E,_),g(E,_),E.push(n.outputColorSpace)),E.push(_.customProgramCacheKey),E.join()}function m(_,E){_.push(E.precision),_.push(E.outputColorSpace),_.push(E.envMapMode),_.push(E.envMapPMREM),_.push(E.envMapMaxLod),_.push(E.envMapSize),_.push(E.mapUv),_.push(E.alphaMapUv),_.push(E.lightMapUv),_.push(E.aoMapUv),_.push(E.bumpMapUv),_.push(E.normalMapUv),_.push(E.displacementMapUv),_.push(E.emissiveMapUv),_.push(E.metalnessMapUv),_.push(E.roughnessMapUv),_.push(E.anisotropyMapUv),_.push(E.clearcoatMapUv),_.push(E.clearcoatNormalMapUv),_.push(E.clearcoatRoughnessMapUv),_.push(E.diffuseRoughnessMapUv),_.push(E.iridescenceMapUv),_.push(E.iridescenceThicknessMapUv),_.push(E.sheenColorMapUv),_.push(E.sheenRoughnessMapUv),_.push(E.specularMapUv),_.push(E.specularColorMapUv),_.push(E.specularIntensityMapUv),_.push(E.transmissionMapUv),_.push(E.thicknessMapUv),_.push(E.combine),_.push(E.fogExp2),_.push(E.sizeAttenuation),_.push(E.morphTargetsCount),_.push(E.numSunLights),_.push(E.numDirLights),_.push(E.numPointLights),_.push(E.numSpotLights),_.push(E.numSpotLightMaps),_.push(E.numHemiLights),_.push(E.numRectAreaLights),_.push(E.numSunLightShadows),_.push(E.numDirLightShadows),_.push(E.numPointLightShadows),_.push(E.numSpotLightShadows),_.push(E.numSpotLightShadowsWithMaps),_.push(E.numLightProbes),_.push(E.numLightProbeGrids),_.push(E.shadowMapType),_.push(E.toneMapping),_.push(E.numClippingPlanes),_.push(E.numClipIntersection),_.push(E.depthPacking)}function g(_,E){o.disableAll(),E.instancing&&o.enable(0),E.instancingColor&&o.enable(1),E.instancingMorph&&o.enable(2),E.matcap&&o.enable(3),E.envMap&&o.enable(4),E.normalMapObjectSpace&&o.enable(5),E.normalMapTangentSpace&&o.enable(6),E.clearcoat&&o.enable(7),E.iridescence&&o.enable(8),E.alphaTest&&o.enable(9),E.vertexColors&&o.enable(10),E.vertexAlphas&&o.enable(11),E.vertexUv1s&&o.enable(12),E.vertexUv2s&&o.enable(13),E.vertexUv3s&&o.enable(14),E.vertexTangents&&o.enable(15),E.anisotropy&&o.enable(16),E.alphaHash&&o.enable(17),E.batching&&o.enable(18),E.dispersion&&o.enable(19),E.retroreflection&&o.enable(24),E.diffuseRoughness&&o.enable(25),E.batchingColor&&o.enable(20),E.gradientMap&&o.enable(21),E.packedNormalMap&&o.enable(22),E.vertexNormals&&o.enable(23),_.push(o.mask),o.disableAll(),E.fog&&o.enable(0),E.useFog&&o.enable(1),E.flatShading&&o.enable(2),E.logarithmicDepthBuffer&&o.enable(3),E.reversedDepthBuffer&&o.enable(4),E.skinning&&o.enable(5),E.morphTargets&&o.enable(6),E.morphNormals&&o.enable(7),E.morphColors&&o.enable(8),E.premultipliedAlpha&&o.enable(9),E.shadowMapEnabled&&o.enable(10),E.doubleSided&&o.enable(11),E.flipSided&&o.enable(12),E.useDepthPacking&&o.enable(13),E.dithering&&o.enable(14),E.transmission&&o.enable(15),E.sheen&&o.enable(16),E.opaque&&o.enable(17),E.pointsUvs&&o.enable(18),E.decodeVideoTexture&&o.enable(19),E.decodeVideoTextureEmissive&&o.enable(20),E.alphaToCoverage&&o.enable(21),E.numLightProbeGrids>0&&o.enable(22),E.hasPositionAttribute&&o.enable(23),_.push(o.mask)}function b(_){let E=f[_.type],F;if(E){let N=vr[E];F=Jb.clone(N.uniforms)}else F=_.uniforms;return F}function T(_,E){let F=u.get(E);return F!==void 0?++F.usedTimes:(F=new hN(n,E,_,r),c.push(F),u.set(E,F)),F}function v(_){if(--_.usedTimes===0){let E=c.indexOf(_);c[E]=c[c.length-1],c.pop(),u.delete(_.cacheKey),_.destroy()}}function R(_){a.remove(_)}function A(){a.dispose()}return{getParameters:p,getProgramCacheKey:x,getUniforms:b,acquireProgram:T,releaseProgram:v,releaseShaderCache:R,programs:c,dispose:A}}function mN(){let n=new WeakMap;function e(o){return n.has(o)}function t(o){let a=n.get(o);return a===void 0&&(a={},n.set(o,a)),a}function i(o){n.delete(o)}function r(o,a,l){n.get(o)[a]=l}function s(){n=new WeakMap}return{has:e,get:t,remove:i,update:r,dispose:s}}function gN(n,e){return n.groupOrder!==e.groupOrder?n.groupOrder-e.groupOrder:n.renderOrder!==e.renderOrder?n.renderOrder-e.renderOrder:n.material.id!==e.material.id?n.material.id-e.material.id:n.materialVariant!==e.materialVariant?n.materialVariant-e.materialVariant:n.z!==e.z?n.z-e.z:n.id-e.id}function _v(n,e){return n.groupOrder!==e.groupOrder?n.groupOrder-e.groupOrder:n.renderOrder!==e.renderOrder?n.renderOrder-e.renderOrder:n.z!==e.z?e.z-n.z:n.id-e.id}function yv(){let n=[],e=0,t=[],i=[],r=[];function s(){e=0,t.length=0,i.length=0,r.length=0}function o(f){let d=0;return f.isInstancedMesh&&(d+=2),f.isSkinnedMesh&&(d+=1),d}function a(f,d,p,x,m,g){let b=n[e];return b===void 0?(b={id:f.id,object:f,geometry:d,material:p,materialVariant:o(f),groupOrder:x,renderOrder:f.renderOrder,z:m,group:g},n[e]=b):(b.id=f.id,b.object=f,b.geometry=d,b.material=p,b.materialVariant=o(f),b.groupOrder=x,b.renderOrder=f.renderOrder,b.z=m,b.group=g),e++,b}function l(f,d,p,x,m,g,b){b.reversedDepth===!0&&(m=-m);let T=a(f,d,p,x,m,g);p.transmission>0?i.push(T):p.transparent===!0?r.push(T):t.push(T)}function c(f,d,p,x,m,g){let b=a(f,d,p,x,m,g);p.transmission>0?i.unshift(b):p.transparent===!0?r.unshift(b):t.unshift(b)}function u(f,d){t.length>1&&t.sort(f||gN),i.length>1&&i.sort(d||_v),r.length>1&&r.sort(d||_v)}function h(){for(let f=e,d=n.length;f<d;f++){let p=n[f];if(p.id===null)break;p.id=null,p.object=null,p.geometry=null,p.material=null,p.group=null}}return{opaque:t,transmissive:i,transparent:r,init:s,push:l,unshift:c,finish:h,sort:u}}function _N(){let n=new WeakMap;function e(i,r){let s=n.get(i),o;return s===void 0?(o=new yv,n.set(i,[o])):r>=s.length?(o=new yv,s.push(o)):o=s[r],o}function t(){n=new WeakMap}return{get:e,dispose:t}}function yN(){let n={};return{get:function(e){if(n[e.id]!==void 0)return n[e.id];let t;switch(e.type){case"SunLight":case"DirectionalLight":t={direction:new X,color:new tt};break;case"SpotLight":t={position:new X,direction:new X,color:new tt,distance:0,coneCos:0,penumbraCos:0,decay:0};break;case"PointLight":t={position:new X,color:new tt,distance:0,decay:0};break;case"HemisphereLight":t={direction:new X,skyColor:new tt,groundColor:new tt};break;case"RectAreaLight":t={color:new tt,position:new X,halfWidth:new X,halfHeight:new X};break}return n[e.id]=t,t}}}function xN(){let n={};return{get:function(e){if(n[e.id]!==void 0)return n[e.id];let t;switch(e.type){case"SunLight":case"DirectionalLight":t={shadowIntensity:1,shadowBias:0,shadowNormalBias:0,shadowRadius:1,shadowMapSize:new Ke};break;case"SpotLight":t={shadowIntensity:1,shadowBias:0,shadowNormalBias:0,shadowRadius:1,shadowMapSize:new Ke};break;case"PointLight":t={shadowIntensity:1,shadowBias:0,shadowNormalBias:0,shadowRadius:1,shadowMapSize:new Ke,shadowCameraNear:1,shadowCameraFar:1e3};break}return n[e.id]=t,t}}}var bN=0;function vN(n,e){return(e.castShadow?2:0)-(n.castShadow?2:0)+(e.map?1:0)-(n.map?1:0)}function SN(n){let e=new yN,t=xN(),i={version:0,hash:{sunLength:-1,directionalLength:-1,pointLength:-1,spotLength:-1,rectAreaLength:-1,hemiLength:-1,numSunShadows:-1,numDirectionalShadows:-1,numPointShadows:-1,numSpotShadows:-1,numSpotMaps:-1,numLightProbes:-1},ambient:[0,0,0],probe:[],sun:[],sunShadow:[],sunShadowMap:[],sunShadowMatrix:[],sunShadowCascade:[],directional:[],directionalShadow:[],directionalShadowMap:[],directionalShadowMatrix:[],spot:[],spotLightMap:[],spotShadow:[],spotShadowMap:[],spotLightMatrix:[],rectArea:[],rectAreaLTC1:null,rectAreaLTC2:null,point:[],pointShadow:[],pointShadowMap:[],pointShadowMatrix:[],hemi:[],numSpotLightShadowsWithMaps:0,numLightProbes:0};for(let c=0;c<9;c++)i.probe.push(new X);let r=new X,s=new Tt,o=new Tt;function a(c){let u=0,h=0,f=0;for(let k=0;k<9;k++)i.probe[k].set(0,0,0);let d=0,p=0,x=0,m=0,g=0,b=0,T=0,v=0,R=0,A=0,_=0,E=0,F=0,N=0;c.sort(vN);for(let k=0,H=c.length;k<H;k++){let D=c[k],W=D.color,K=D.intensity,z=D.distance,ce=null;if(D.shadow&&D.shadow.map&&(D.shadow.map.texture.format===bs?ce=D.shadow.map.texture:ce=D.shadow.map.depthTexture||D.shadow.map.texture),D.isAmbientLight)u+=W.r*K,h+=W.g*K,f+=W.b*K;else if(D.isLightProbe){for(let J=0;J<9;J++)i.probe[J].addScaledVector(D.sh.coefficients[J],K);N++}else if(D.isSunLight){let J=e.get(D);if(J.color.copy(D.color).multiplyScalar(D.intensity),D.castShadow){let Q=D.shadow,re=t.get(D);re.shadowIntensity=Q.intensity,re.shadowBias=Q.bias,re.shadowNormalBias=Q.normalBias,re.shadowRadius=Q.radius,re.shadowMapSize.copy(Q.mapSize).multiply(Q.getFrameExtents()),i.sunShadow[p]=re,i.sunShadowMap[p]=ce;let fe=Q.getViewportCount();for(let he=0;he<fe;he++)i.sunShadowMatrix[x+he]=Q.getMatrix(he),i.sunShadowCascade[x+he]=Q._cascadeData[he];x+=fe,p++}i.sun[d]=J,d++}else if(D.isDirectionalLight){let J=e.get(D);if(J.color.copy(D.color).multiplyScalar(D.intensity),D.castShadow){let Q=D.shadow,re=t.get(D);re.shadowIntensity=Q.intensity,re.shadowBias=Q.bias,re.shadowNormalBias=Q.normalBias,re.shadowRadius=Q.radius,re.shadowMapSize=Q.mapSize,i.directionalShadow[m]=re,i.directionalShadowMap[m]=ce,i.directionalShadowMatrix[m]=D.shadow.matrix,R++}i.directional[m]=J,m++}else if(D.isSpotLight){let J=e.get(D);J.position.setFromMatrixPosition(D.matrixWorld),J.color.copy(W).multiplyScalar(K),J.distance=z,J.coneCos=Math.cos(D.angle),J.penumbraCos=Math.cos(D.angle*(1-D.penumbra)),J.decay=D.decay,i.spot[b]=J;let Q=D.shadow;if(D.map&&(i.spotLightMap[E]=D.map,E++,Q.updateMatrices(D),D.castShadow&&F++),i.spotLightMatrix[b]=Q.matrix,D.castShadow){let re=t.get(D);re.shadowIntensity=Q.intensity,re.shadowBias=Q.bias,re.shadowNormalBias=Q.normalBias,re.shadowRadius=Q.radius,re.shadowMapSize=Q.mapSize,i.spotShadow[b]=re,i.spotShadowMap[b]=ce,_++}b++}else if(D.isRectAreaLight){let J=e.get(D);J.color.copy(W).multiplyScalar(K),J.halfWidth.set(D.width*.5,0,0),J.halfHeight.set(0,D.height*.5,0),i.rectArea[T]=J,T++}else if(D.isPointLight){let J=e.get(D);if(J.color.copy(D.color).multiplyScalar(D.intensity),J.distance=D.distance,J.decay=D.decay,D.castShadow){let Q=D.shadow,re=t.get(D);re.shadowIntensity=Q.intensity,re.shadowBias=Q.bias,re.shadowNormalBias=Q.normalBias,re.shadowRadius=Q.radius,re.shadowMapSize=Q.mapSize,re.shadowCameraNear=Q.camera.near,re.shadowCameraFar=Q.camera.far,i.pointShadow[g]=re,i.pointShadowMap[g]=ce,i.pointShadowMatrix[g]=D.shadow.matrix,A++}i.point[g]=J,g++}else if(D.isHemisphereLight){let J=e.get(D);J.skyColor.copy(D.color).multiplyScalar(K),J.groundColor.copy(D.groundColor).multiplyScalar(K),i.hemi[v]=J,v++}}T>0&&(n.has("OES_texture_float_linear")===!0?(i.rectAreaLTC1=Pe.LTC_FLOAT_1,i.rectAreaLTC2=Pe.LTC_FLOAT_2):(i.rectAreaLTC1=Pe.LTC_HALF_1,i.rectAreaLTC2=Pe.LTC_HALF_2)),i.ambient[0]=u,i.ambient[1]=h,i.ambient[2]=f;let P=i.hash;(P.sunLength!==d||P.directionalLength!==m||P.pointLength!==g||P.spotLength!==b||P.rectAreaLength!==T||P.hemiLength!==v||P.numSunShadows!==p||P.numDirectionalShadows!==R||P.numPointShadows!==A||P.numSpotShadows!==_||P.numSpotMaps!==E||P.numLightProbes!==N)&&(i.sun.length=d,i.directional.length=m,i.spot.length=b,i.rectArea.length=T,i.point.length=g,i.hemi.length=v,i.sunShadow.length=p,i.sunShadowMap.length=p,i.sunShadowMatrix.length=x,i.sunShadowCascade.length=x,i.directionalShadow.length=R,i.directionalShadowMap.length=R,i.directionalShadowMatrix.length=R,i.pointShadow.length=A,i.pointShadowMap.length=A,i.pointShadowMatrix.length=A,i.spotShadow.length=_,i.spotShadowMap.length=_,i.spotLightMatrix.length=_+E-F,i.spotLightMap.length=E,i.numSpotLightShadowsWithMaps=F,i.numLightProbes=N,P.sunLength=d,P.directionalLength=m,P.pointLength=g,P.spotLength=b,P.rectAreaLength=T,P.hemiLength=v,P.numSunShadows=p,P.numDirectionalShadows=R,P.numPointShadows=A,P.numSpotShadows=_,P.numSpotMaps=E,P.numLightProbes=N,i.version=bN++)}function l(c,u){let h=0,f=0,d=0,p=0,x=0,m=0,g=u.matrixWorldInverse;for(let b=0,T=c.length;b<T;b++){let v=c[b];if(v.isSunLight){let R=i.sun[h];R.direction.setFromMatrixPosition(v.matrixWorld),R.direction.transformDirection(g),h++}else if(v.isDirectionalLight){let R=i.directional[f];R.direction.setFromMatrixPosition(v.matrixWorld),r.setFromMatrixPosition(v.target.matrixWorld),R.direction.sub(r),R.direction.transformDirection(g),f++}else if(v.isSpotLight){let R=i.spot[p];R.position.setFromMatrixPosition(v.matrixWorld),R.position.applyMatrix4(g),R.direction.setFromMatrixPosition(v.matrixWorld),r.setFromMatrixPosition(v.target.matrixWorld),R.direction.sub(r),R.direction.transformDirection(g),p++}else if(v.isRectAreaLight){let R=i.rectArea[x];R.position.setFromMatrixPosition(v.matrixWorld),R.position.applyMatrix4(g),o.identity(),s.copy(v.matrixWorld),s.premultiply(g),o.extractRotation(s),R.halfWidth.set(v.width*.5,0,0),R.halfHeight.set(0,v.height*.5,0),R.halfWidth.applyMatrix4(o),R.halfHeight.applyMatrix4(o),x++}else if(v.isPointLight){let R=i.point[d];R.position.setFromMatrixPosition(v.matrixWorld),R.position.applyMatrix4(g),d++}else if(v.isHemisphereLight){let R=i.hemi[m];R.direction.setFromMatrixPosition(v.matrixWorld),R.direction.transformDirection(g),m++}}}return{setup:a,setupView:l,state:i}}function xv(n){let e=new SN(n),t=[],i=[],r=[];function s(h){u.camera=h,t.length=0,i.length=0,r.length=0}function o(h){h.isLightProbeGrid?r.push(h):t.push(h)}function a(h){i.push(h)}function l(){e.setup(t),r.sort((h,f)=>h.priority-f.priority||h.id-f.id)}function c(h){e.setupView(t,h)}let u={lightsArray:t,shadowsArray:i,lightProbeGridArray:r,camera:null,lights:e,transmissionRenderTarget:{},textureUnits:0};return{init:s,state:u,setupLights:l,setupLightsView:c,pushLight:o,pushShadow:a}}function EN(n){let e=new WeakMap;function t(r,s=0){let o=e.get(r),a;return o===void 0?(a=new xv(n),e.set(r,[a])):s>=o.length?(a=new xv(n),o.push(a)):a=o[s],a}function i(){e=new WeakMap}return{get:t,dispose:i}}var MN=`void main() {
	gl_Position = vec4( position, 1.0 );
}`,wN=`uniform sampler2D shadow_pass;
uniform vec2 resolution;
uniform float radius;
void main() {
	const float samples = float( VSM_SAMPLES );
	float mean = 0.0;
	float squared_mean = 0.0;
	float uvStride = samples <= 1.0 ? 0.0 : 2.0 / ( samples - 1.0 );
	float uvStart = samples <= 1.0 ? 0.0 : - 1.0;
	for ( float i = 0.0; i < samples; i ++ ) {
		float uvOffset = uvStart + i * uvStride;
		#ifdef HORIZONTAL_PASS
			vec2 distribution = texture2D( shadow_pass, ( gl_FragCoord.xy + vec2( uvOffset, 0.0 ) * radius ) / resolution ).rg;
			mean += distribution.x;
			squared_mean += distribution.y * distribution.y + distribution.x * distribution.x;
		#else
			float depth = texture2D( shadow_pass, ( gl_FragCoord.xy + vec2( 0.0, uvOffset ) * radius ) / resolution ).r;
			mean += depth;
			squared_mean += depth * depth;
		#endif
	}
	mean = mean / samples;
	squared_mean = squared_mean / samples;
	float std_dev = sqrt( max( 0.0, squared_mean - mean * mean ) );
	gl_FragColor = vec4( mean, std_dev, 0.0, 1.0 );
}`,TN=[new X(1,0,0),new X(-1,0,0),new X(0,1,0),new X(0,-1,0),new X(0,0,1),new X(0,0,-1)],AN=[new X(0,-1,0),new X(0,-1,0),new X(0,0,1),new X(0,0,-1),new X(0,-1,0),new X(0,-1,0)],bv=new Tt,Dl=new X,ym=new X;function RN(n,e,t){let i=new fs,r=new Ke,s=new Ke,o=new tn,a=new Xu,l=new Yu,c={},u=t.maxTextureSize,h={[xs]:si,[si]:xs,[yr]:yr},f=new _r({defines:{VSM_SAMPLES:8},uniforms:{shadow_pass:{value:null},resolution:{value:new Ke},radius:{value:4}},vertexShader:MN,fragmentShader:wN}),d=f.clone();d.defines.HORIZONTAL_PASS=1;let p=new Gn;p.setAttribute("position",new kn(new Float32Array([-1,-1,.5,3,-1,.5,-1,3,.5]),3));let x=new Fi(p,f),m=this;this.enabled=!1,this.autoUpdate=!0,this.needsUpdate=!1,this.type=Tl;let g=this.type;this.render=function(A,_,E){if(m.enabled===!1||m.autoUpdate===!1&&m.needsUpdate===!1||A.length===0)return;this.type===db&&($e("WebGLShadowMap: PCFSoftShadowMap has been removed. Using PCFShadowMap instead."),this.type=Tl);let F=n.getRenderTarget(),N=n.getActiveCubeFace(),P=n.getActiveMipmapLevel(),k=n.state;k.setBlending(Gs),k.buffers.depth.getReversed()===!0?k.buffers.color.setClear(0,0,0,0):k.buffers.color.setClear(1,1,1,1),k.buffers.depth.setTest(!0),k.setScissorTest(!1);let H=g!==this.type;H&&_.traverse(function(D){D.material&&(Array.isArray(D.material)?D.material.forEach(W=>W.needsUpdate=!0):D.material.needsUpdate=!0)});for(let D=0,W=A.length;D<W;D++){let K=A[D],z=K.shadow;if(z===void 0){$e("WebGLShadowMap:",K,"has no shadow.");continue}if(z.autoUpdate===!1&&z.needsUpdate===!1)continue;r.copy(z.mapSize);let ce=z.getFrameExtents();r.multiply(ce),s.copy(z.mapSize),(r.x>u||r.y>u)&&(r.x>u&&(s.x=Math.floor(u/ce.x),r.x=s.x*ce.x,z.mapSize.x=s.x),r.y>u&&(s.y=Math.floor(u/ce.y),r.y=s.y*ce.y,z.mapSize.y=s.y));let J=n.state.buffers.depth.getReversed();if(z.camera._reversedDepth=J,z.map===null||H===!0){if(z.map!==null&&(z.map.depthTexture!==null&&(z.map.depthTexture.dispose(),z.map.depthTexture=null),z.map.dispose()),this.type===Qo){if(K.isPointLight){$e("WebGLShadowMap: VSM shadow maps are not supported for PointLights. Use PCF or BasicShadowMap instead.");continue}z.map=new wi(r.x,r.y,{format:bs,type:Qi,minFilter:ri,magFilter:ri,generateMipmaps:!1}),z.map.texture.name=K.name+".shadowMap",z.map.depthTexture=new zr(r.x,r.y,Ui),z.map.depthTexture.name=K.name+".shadowMapDepth",z.map.depthTexture.format=kr,z.map.depthTexture.compareFunction=null,z.map.depthTexture.minFilter=Vn,z.map.depthTexture.magFilter=Vn}else K.isPointLight?(z.map=new Ul(r.x),z.map.depthTexture=new fl(r.x,ji)):(z.map=new wi(r.x,r.y),z.map.depthTexture=new zr(r.x,r.y,ji)),z.map.depthTexture.name=K.name+".shadowMap",z.map.depthTexture.format=kr,this.type===Tl?(z.map.depthTexture.compareFunction=J?om:sm,z.map.depthTexture.minFilter=ri,z.map.depthTexture.magFilter=ri):(z.map.depthTexture.compareFunction=null,z.map.depthTexture.minFilter=Vn,z.map.depthTexture.magFilter=Vn);z.camera.updateProjectionMatrix()}z.map.isWebGLCubeRenderTarget!==!0&&(z.map.width!==r.x||z.map.height!==r.y)&&z.map.setSize(r.x,r.y);let Q=z.map.isWebGLCubeRenderTarget?6:z.getViewportCount();K.isPointLight!==!0&&z.updateMatrices(K,E);let re=(z.camera.layers.mask&4294967294)!==0?z.camera.layers:E.layers;for(let fe=0;fe<Q;fe++){let he=z.getCamera(fe);if(K.isPointLight){let ee=z.camera,me=z.matrix,ye=K.distance||ee.far;ye!==ee.far&&(ee.far=ye,ee.updateProjectionMatrix()),Dl.setFromMatrixPosition(K.matrixWorld),ee.position.copy(Dl),ym.copy(ee.position),ym.add(TN[fe]),ee.up.copy(AN[fe]),ee.lookAt(ym),ee.updateMatrixWorld(),me.makeTranslation(-Dl.x,-Dl.y,-Dl.z),bv.multiplyMatrices(ee.projectionMatrix,ee.matrixWorldInverse),z._frustum.setFromProjectionMatrix(bv,ee.coordinateSystem,ee.reversedDepth)}if(z.map.isWebGLCubeRenderTarget)n.setRenderTarget(z.map,fe),n.clear();else{fe===0&&(n.setRenderTarget(z.map),n.clear());let ee=z.getViewport(fe);o.set(s.x*ee.x,s.y*ee.y,s.x*ee.z,s.y*ee.w),k.viewport(o)}i=z.getFrustum(fe),v(_,E,he,K,re,this.type)}z.isPointLightShadow!==!0&&this.type===Qo&&b(z,E),z.needsUpdate=!1}g=this.type,m.needsUpdate=!1,n.setRenderTarget(F,N,P)};function b(A,_){let E=e.update(x);f.defines.VSM_SAMPLES!==A.blurSamples&&(f.defines.VSM_SAMPLES=A.blurSamples,d.defines.VSM_SAMPLES=A.blurSamples,f.needsUpdate=!0,d.needsUpdate=!0),A.mapPass===null?A.mapPass=new wi(r.x,r.y,{format:bs,type:Qi}):(A.mapPass.width!==A.map.width||A.mapPass.height!==A.map.height)&&A.mapPass.setSize(A.map.width,A.map.height),f.uniforms.shadow_pass.value=A.map.depthTexture,f.uniforms.resolution.value.set(A.map.width,A.map.height),f.uniforms.radius.value=A.radius,n.setRenderTarget(A.mapPass),n.clear(),n.renderBufferDirect(_,null,E,f,x,null),d.uniforms.shadow_pass.value=A.mapPass.texture,d.uniforms.resolution.value.set(A.map.width,A.map.height),d.uniforms.radius.value=A.radius,n.setRenderTarget(A.map),n.clear(),n.renderBufferDirect(_,null,E,d,x,null)}function T(A,_,E,F){let N=null,P=E.isPointLight===!0?A.customDistanceMaterial:A.customDepthMaterial;if(P!==void 0)N=P;else if(N=E.isPointLight===!0?l:a,n.localClippingEnabled&&_.clipShadows===!0&&Array.isArray(_.clippingPlanes)&&_.clippingPlanes.length!==0||_.displacementMap&&_.displacementScale!==0||_.alphaMap&&_.alphaTest>0||_.map&&_.alphaTest>0||_.alphaToCoverage===!0){let k=N.uuid,H=_.uuid,D=c[k];D===void 0&&(D={},c[k]=D);let W=D[H];W===void 0&&(W=N.clone(),D[H]=W,_.addEventListener("dispose",R)),N=W}if(N.visible=_.visible,N.wireframe=_.wireframe,F===Qo?N.side=_.shadowSide!==null?_.shadowSide:_.side:N.side=_.shadowSide!==null?_.shadowSide:h[_.side],N.alphaMap=_.alphaMap,N.alphaTest=_.alphaToCoverage===!0?.5:_.alphaTest,N.map=_.map,N.clipShadows=_.clipShadows,N.clippingPlanes=_.clippingPlanes,N.clipIntersection=_.clipIntersection,N.displacementMap=_.displacementMap,N.displacementScale=_.displacementScale,N.displacementBias=_.displacementBias,N.wireframeLinewidth=_.wireframeLinewidth,N.linewidth=_.linewidth,E.isPointLight===!0&&N.isMeshDistanceMaterial===!0){let k=n.properties.get(N);k.light=E}return N}function v(A,_,E,F,N,P){if(A.visible===!1)return;if(A.layers.test(N)&&(A.isMesh||A.isLine||A.isPoints)&&(A.castShadow||A.receiveShadow&&P===Qo)&&(!A.frustumCulled||A.intersectsFrustum(i))){A.modelViewMatrix.multiplyMatrices(E.matrixWorldInverse,A.matrixWorld);let D=e.update(A),W=A.material;if(Array.isArray(W)){let K=D.groups;for(let z=0,ce=K.length;z<ce;z++){let J=K[z],Q=W[J.materialIndex];if(Q&&Q.visible){let re=T(A,Q,F,P);A.onBeforeShadow(n,A,_,E,D,re,J),n.renderBufferDirect(E,null,D,re,A,J),A.onAfterShadow(n,A,_,E,D,re,J)}}}else if(W.visible){let K=T(A,W,F,P);A.onBeforeShadow(n,A,_,E,D,K,null),n.renderBufferDirect(E,null,D,K,A,null),A.onAfterShadow(n,A,_,E,D,K,null)}}let H=A.children;for(let D=0,W=H.length;D<W;D++)v(H[D],_,E,F,N,P)}function R(A){A.target.removeEventListener("dispose",R);for(let E in c){let F=c[E],N=A.target.uuid;N in F&&(F[N].dispose(),delete F[N])}}}function IN(n,e){function t(){let U=!1,se=new tn,ne=null,Me=new tn(0,0,0,0);return{setMask:function(ge){ne!==ge&&!U&&(n.colorMask(ge,ge,ge,ge),ne=ge)},setLocked:function(ge){U=ge},setClear:function(ge,ve,He,je,le){le===!0&&(ge*=je,ve*=je,He*=je),se.set(ge,ve,He,je),Me.equals(se)===!1&&(n.clearColor(ge,ve,He,je),Me.copy(se))},reset:function(){U=!1,ne=null,Me.set(-1,0,0,0)}}}function i(){let U=!1,se=!1,ne=null,Me=null,ge=null;return{setReversed:function(ve){if(se!==ve){let He=e.get("EXT_clip_control");ve?He.clipControlEXT(He.LOWER_LEFT_EXT,He.ZERO_TO_ONE_EXT):He.clipControlEXT(He.LOWER_LEFT_EXT,He.NEGATIVE_ONE_TO_ONE_EXT),se=ve;let je=ge;ge=null,this.setClear(je)}},getReversed:function(){return se},setTest:function(ve){ve?Se(n.DEPTH_TEST):Xe(n.DEPTH_TEST)},setMask:function(ve){ne!==ve&&!U&&(n.depthMask(ve),ne=ve)},setFunc:function(ve){if(se&&(ve=Zb[ve]),Me!==ve){switch(ve){case Mu:n.depthFunc(n.NEVER);break;case wu:n.depthFunc(n.ALWAYS);break;case Tu:n.depthFunc(n.LESS);break;case zo:n.depthFunc(n.LEQUAL);break;case Au:n.depthFunc(n.EQUAL);break;case Ru:n.depthFunc(n.GEQUAL);break;case Iu:n.depthFunc(n.GREATER);break;case Cu:n.depthFunc(n.NOTEQUAL);break;default:n.depthFunc(n.LEQUAL)}Me=ve}},setLocked:function(ve){U=ve},setClear:function(ve){ge!==ve&&(ge=ve,se&&(ve=1-ve),n.clearDepth(ve))},reset:function(){U=!1,ne=null,Me=null,ge=null,se=!1}}}function r(){let U=!1,se=null,ne=null,Me=null,ge=null,ve=null,He=null,je=null,le=null;return{setTest:function(Be){U||(Be?Se(n.STENCIL_TEST):Xe(n.STENCIL_TEST))},setMask:function(Be){se!==Be&&!U&&(n.stencilMask(Be),se=Be)},setFunc:function(Be,Qe,Re){(ne!==Be||Me!==Qe||ge!==Re)&&(n.stencilFunc(Be,Qe,Re),ne=Be,Me=Qe,ge=Re)},setOp:function(Be,Qe,Re){(ve!==Be||He!==Qe||je!==Re)&&(n.stencilOp(Be,Qe,Re),ve=Be,He=Qe,je=Re)},setLocked:function(Be){U=Be},setClear:function(Be){le!==Be&&(n.clearStencil(Be),le=Be)},reset:function(){U=!1,se=null,ne=null,Me=null,ge=null,ve=null,He=null,je=null,le=null}}}let s=new t,o=new i,a=new r,l={},c=new WeakMap,u={},h={},f={},d=new WeakMap,p=[],x=null,m=!1,g=null,b=null,T=null,v=null,R=null,A=null,_=null,E=new tt(0,0,0),F=0,N=!1,P=null,k=null,H=null,D=null,W=null,K=n.getParameter(n.MAX_COMBINED_TEXTURE_IMAGE_UNITS),z=!1,ce=0,J=n.getParameter(n.VERSION);J.indexOf("WebGL")!==-1?(ce=parseFloat(/^WebGL (\d)/.exec(J)[1]),z=ce>=1):J.indexOf("OpenGL ES")!==-1&&(ce=parseFloat(/^OpenGL ES (\d)/.exec(J)[1]),z=ce>=2);let Q=null,re={},fe=n.getParameter(n.SCISSOR_BOX),he=n.getParameter(n.VIEWPORT),ee=new tn().fromArray(fe),me=new tn().fromArray(he);function ye(U,se,ne,Me){let ge=new Uint8Array(4),ve=n.createTexture();n.bindTexture(U,ve),n.texParameteri(U,n.TEXTURE_MIN_FILTER,n.NEAREST),n.texParameteri(U,n.TEXTURE_MAG_FILTER,n.NEAREST);for(let He=0;He<ne;He++)U===n.TEXTURE_3D||U===n.TEXTURE_2D_ARRAY?n.texImage3D(se,0,n.RGBA,1,1,Me,0,n.RGBA,n.UNSIGNED_BYTE,ge):n.texImage2D(se+He,0,n.RGBA,1,1,0,n.RGBA,n.UNSIGNED_BYTE,ge);return ve}let Ae={};Ae[n.TEXTURE_2D]=ye(n.TEXTURE_2D,n.TEXTURE_2D,1),Ae[n.TEXTURE_CUBE_MAP]=ye(n.TEXTURE_CUBE_MAP,n.TEXTURE_CUBE_MAP_POSITIVE_X,6),Ae[n.TEXTURE_2D_ARRAY]=ye(n.TEXTURE_2D_ARRAY,n.TEXTURE_2D_ARRAY,1,1),Ae[n.TEXTURE_3D]=ye(n.TEXTURE_3D,n.TEXTURE_3D,1,1),s.setClear(0,0,0,1),o.setClear(1),a.setClear(0),Se(n.DEPTH_TEST),o.setFunc(zo),mn(!1),Ot(kp),Se(n.CULL_FACE),Qt(Gs);function Se(U){u[U]!==!0&&(n.enable(U),u[U]=!0)}function Xe(U){u[U]!==!1&&(n.disable(U),u[U]=!1)}function ot(U,se){return f[U]!==se?(n.bindFramebuffer(U,se),f[U]=se,U===n.DRAW_FRAMEBUFFER&&(f[n.FRAMEBUFFER]=se),U===n.FRAMEBUFFER&&(f[n.DRAW_FRAMEBUFFER]=se),!0):!1}function ze(U,se){let ne=p,Me=!1;if(U){ne=d.get(se),ne===void 0&&(ne=[],d.set(se,ne));let ge=U.textures;if(ne.length!==ge.length||ne[0]!==n.COLOR_ATTACHMENT0){for(let ve=0,He=ge.length;ve<He;ve++)ne[ve]=n.COLOR_ATTACHMENT0+ve;ne.length=ge.length,Me=!0}}else ne[0]!==n.BACK&&(ne[0]=n.BACK,Me=!0);Me&&n.drawBuffers(ne)}function ft(U){return x!==U?(n.useProgram(U),x=U,!0):!1}let ct={[zs]:n.FUNC_ADD,[mb]:n.FUNC_SUBTRACT,[gb]:n.FUNC_REVERSE_SUBTRACT};ct[_b]=n.MIN,ct[yb]=n.MAX;let rt={[xb]:n.ZERO,[bb]:n.ONE,[vb]:n.SRC_COLOR,[Hp]:n.SRC_ALPHA,[Ab]:n.SRC_ALPHA_SATURATE,[wb]:n.DST_COLOR,[Eb]:n.DST_ALPHA,[Sb]:n.ONE_MINUS_SRC_COLOR,[Wp]:n.ONE_MINUS_SRC_ALPHA,[Tb]:n.ONE_MINUS_DST_COLOR,[Mb]:n.ONE_MINUS_DST_ALPHA,[Rb]:n.CONSTANT_COLOR,[Ib]:n.ONE_MINUS_CONSTANT_COLOR,[Cb]:n.CONSTANT_ALPHA,[Nb]:n.ONE_MINUS_CONSTANT_ALPHA};function Qt(U,se,ne,Me,ge,ve,He,je,le,Be){if(U===Gs){m===!0&&(Xe(n.BLEND),m=!1);return}if(m===!1&&(Se(n.BLEND),m=!0),U!==pb){if(U!==g||Be!==N){if((b!==zs||R!==zs)&&(n.blendEquation(n.FUNC_ADD),b=zs,R=zs),Be)switch(U){case ea:n.blendFuncSeparate(n.ONE,n.ONE_MINUS_SRC_ALPHA,n.ONE,n.ONE_MINUS_SRC_ALPHA);break;case Vp:n.blendFunc(n.ONE,n.ONE);break;case Gp:n.blendFuncSeparate(n.ZERO,n.ONE_MINUS_SRC_COLOR,n.ZERO,n.ONE);break;case zp:n.blendFuncSeparate(n.DST_COLOR,n.ONE_MINUS_SRC_ALPHA,n.ZERO,n.ONE);break;default:et("WebGLState: Invalid blending: ",U);break}else switch(U){case ea:n.blendFuncSeparate(n.SRC_ALPHA,n.ONE_MINUS_SRC_ALPHA,n.ONE,n.ONE_MINUS_SRC_ALPHA);break;case Vp:n.blendFuncSeparate(n.SRC_ALPHA,n.ONE,n.ONE,n.ONE);break;case Gp:et("WebGLState: SubtractiveBlending requires material.premultipliedAlpha = true");break;case zp:et("WebGLState: MultiplyBlending requires material.premultipliedAlpha = true");break;default:et("WebGLState: Invalid blending: ",U);break}T=null,v=null,A=null,_=null,E.set(0,0,0),F=0,g=U,N=Be}return}ge=ge||se,ve=ve||ne,He=He||Me,(se!==b||ge!==R)&&(n.blendEquationSeparate(ct[se],ct[ge]),b=se,R=ge),(ne!==T||Me!==v||ve!==A||He!==_)&&(n.blendFuncSeparate(rt[ne],rt[Me],rt[ve],rt[He]),T=ne,v=Me,A=ve,_=He),(je.equals(E)===!1||le!==F)&&(n.blendColor(je.r,je.g,je.b,le),E.copy(je),F=le),g=U,N=!1}function Xt(U,se){U.side===yr?Xe(n.CULL_FACE):Se(n.CULL_FACE);let ne=U.side===si;se&&(ne=!ne),mn(ne),U.blending===ea&&U.transparent===!1?Qt(Gs):Qt(U.blending,U.blendEquation,U.blendSrc,U.blendDst,U.blendEquationAlpha,U.blendSrcAlpha,U.blendDstAlpha,U.blendColor,U.blendAlpha,U.premultipliedAlpha),o.setFunc(U.depthFunc),o.setTest(U.depthTest),o.setMask(U.depthWrite),s.setMask(U.colorWrite);let Me=U.stencilWrite;a.setTest(Me),Me&&(a.setMask(U.stencilWriteMask),a.setFunc(U.stencilFunc,U.stencilRef,U.stencilFuncMask),a.setOp(U.stencilFail,U.stencilZFail,U.stencilZPass)),wt(U.polygonOffset,U.polygonOffsetFactor,U.polygonOffsetUnits),U.alphaToCoverage===!0?Se(n.SAMPLE_ALPHA_TO_COVERAGE):Xe(n.SAMPLE_ALPHA_TO_COVERAGE)}function mn(U){P!==U&&(U?n.frontFace(n.CW):n.frontFace(n.CCW),P=U)}function Ot(U){U!==hb?(Se(n.CULL_FACE),U!==k&&(U===kp?n.cullFace(n.BACK):U===fb?n.cullFace(n.FRONT):n.cullFace(n.FRONT_AND_BACK))):Xe(n.CULL_FACE),k=U}function Ln(U){U!==H&&(z&&n.lineWidth(U),H=U)}function wt(U,se,ne){U?(Se(n.POLYGON_OFFSET_FILL),(D!==se||W!==ne)&&(D=se,W=ne,o.getReversed()&&(se=-se,ne=-ne),n.polygonOffset(se,ne))):Xe(n.POLYGON_OFFSET_FILL)}function Mn(U){U?Se(n.SCISSOR_TEST):Xe(n.SCISSOR_TEST)}function sn(U){U===void 0&&(U=n.TEXTURE0+K-1),Q!==U&&(n.activeTexture(U),Q=U)}function gn(U,se,ne){ne===void 0&&(Q===null?ne=n.TEXTURE0+K-1:ne=Q);let Me=re[ne];Me===void 0&&(Me={type:void 0,texture:void 0},re[ne]=Me),(Me.type!==U||Me.texture!==se)&&(Q!==ne&&(n.activeTexture(ne),Q=ne),n.bindTexture(U,se||Ae[U]),Me.type=U,Me.texture=se)}function O(){let U=re[Q];U!==void 0&&U.type!==void 0&&(n.bindTexture(U.type,null),U.type=void 0,U.texture=void 0)}function Ie(){try{n.compressedTexImage2D(...arguments)}catch(U){et("WebGLState:",U)}}function qe(){try{n.compressedTexImage3D(...arguments)}catch(U){et("WebGLState:",U)}}function at(){try{n.texSubImage2D(...arguments)}catch(U){et("WebGLState:",U)}}function Ee(){try{n.texSubImage3D(...arguments)}catch(U){et("WebGLState:",U)}}function Vt(){try{n.compressedTexSubImage2D(...arguments)}catch(U){et("WebGLState:",U)}}function Ge(){try{n.compressedTexSubImage3D(...arguments)}catch(U){et("WebGLState:",U)}}function Ze(){try{n.texStorage2D(...arguments)}catch(U){et("WebGLState:",U)}}function I(){try{n.texStorage3D(...arguments)}catch(U){et("WebGLState:",U)}}function S(){try{n.texImage2D(...arguments)}catch(U){et("WebGLState:",U)}}function Y(){try{n.texImage3D(...arguments)}catch(U){et("WebGLState:",U)}}function ue(U){return h[U]!==void 0?h[U]:n.getParameter(U)}function oe(U,se){h[U]!==se&&(n.pixelStorei(U,se),h[U]=se)}function _e(U){ee.equals(U)===!1&&(n.scissor(U.x,U.y,U.z,U.w),ee.copy(U))}function xe(U){me.equals(U)===!1&&(n.viewport(U.x,U.y,U.z,U.w),me.copy(U))}function te(U,se){let ne=c.get(se);ne===void 0&&(ne=new WeakMap,c.set(se,ne));let Me=ne.get(U);Me===void 0&&(Me=n.getUniformBlockIndex(se,U.name),n.uniformBlockBinding(se,Me,Me),ne.set(U,Me))}function ie(U,se,ne){let ge=c.get(se).get(U);l[ge]!==ne&&(n.bindBufferBase(n.UNIFORM_BUFFER,ge,ne),l[ge]=ne)}function pe(){n.disable(n.BLEND),n.disable(n.CULL_FACE),n.disable(n.DEPTH_TEST),n.disable(n.POLYGON_OFFSET_FILL),n.disable(n.SCISSOR_TEST),n.disable(n.STENCIL_TEST),n.disable(n.SAMPLE_ALPHA_TO_COVERAGE),n.blendEquation(n.FUNC_ADD),n.blendFunc(n.ONE,n.ZERO),n.blendFuncSeparate(n.ONE,n.ZERO,n.ONE,n.ZERO),n.blendColor(0,0,0,0),n.colorMask(!0,!0,!0,!0),n.clearColor(0,0,0,0),n.depthMask(!0),n.depthFunc(n.LESS),o.setReversed(!1),n.clearDepth(1),n.stencilMask(4294967295),n.stencilFunc(n.ALWAYS,0,4294967295),n.stencilOp(n.KEEP,n.KEEP,n.KEEP),n.clearStencil(0),n.cullFace(n.BACK),n.frontFace(n.CCW),n.polygonOffset(0,0),n.activeTexture(n.TEXTURE0),n.bindFramebuffer(n.FRAMEBUFFER,null),n.bindFramebuffer(n.DRAW_FRAMEBUFFER,null),n.bindFramebuffer(n.READ_FRAMEBUFFER,null),n.useProgram(null),n.lineWidth(1),n.scissor(0,0,n.canvas.width,n.canvas.height),n.viewport(0,0,n.canvas.width,n.canvas.height),n.pixelStorei(n.PACK_ALIGNMENT,4),n.pixelStorei(n.UNPACK_ALIGNMENT,4),n.pixelStorei(n.UNPACK_FLIP_Y_WEBGL,!1),n.pixelStorei(n.UNPACK_PREMULTIPLY_ALPHA_WEBGL,!1),n.pixelStorei(n.UNPACK_COLORSPACE_CONVERSION_WEBGL,n.BROWSER_DEFAULT_WEBGL),n.pixelStorei(n.PACK_ROW_LENGTH,0),n.pixelStorei(n.PACK_SKIP_PIXELS,0),n.pixelStorei(n.PACK_SKIP_ROWS,0),n.pixelStorei(n.UNPACK_ROW_LENGTH,0),n.pixelStorei(n.UNPACK_IMAGE_HEIGHT,0),n.pixelStorei(n.UNPACK_SKIP_PIXELS,0),n.pixelStorei(n.UNPACK_SKIP_ROWS,0),n.pixelStorei(n.UNPACK_SKIP_IMAGES,0),u={},h={},Q=null,re={},f={},l={},d=new WeakMap,p=[],x=null,m=!1,g=null,b=null,T=null,v=null,R=null,A=null,_=null,E=new tt(0,0,0),F=0,N=!1,P=null,k=null,H=null,D=null,W=null,ee.set(0,0,n.canvas.width,n.canvas.height),me.set(0,0,n.canvas.width,n.canvas.height),s.reset(),o.reset(),a.reset()}return{buffers:{color:s,depth:o,stencil:a},enable:Se,disable:Xe,bindFramebuffer:ot,drawBuffers:ze,useProgram:ft,setBlending:Qt,setMaterial:Xt,setFlipSided:mn,setCullFace:Ot,setLineWidth:Ln,setPolygonOffset:wt,setScissorTest:Mn,activeTexture:sn,bindTexture:gn,unbindTexture:O,compressedTexImage2D:Ie,compressedTexImage3D:qe,texImage2D:S,texImage3D:Y,pixelStorei:oe,getParameter:ue,updateUBOMapping:te,uniformBlockBinding:ie,texStorage2D:Ze,texStorage3D:I,texSubImage2D:at,texSubImage3D:Ee,compressedTexSubImage2D:Vt,compressedTexSubImage3D:Ge,scissor:_e,viewport:xe,reset:pe}}function CN(n,e,t,i,r,s,o){let a=e.has("WEBGL_multisampled_render_to_texture")?e.get("WEBGL_multisampled_render_to_texture"):null,l=typeof navigator>"u"?!1:/OculusBrowser/g.test(navigator.userAgent),c=new Ke,u=new WeakMap,h=new Set,f,d=new WeakMap,p=new Set,x=new FinalizationRegistry(I=>p.delete(I)),m=!1;try{m=typeof OffscreenCanvas<"u"&&new OffscreenCanvas(1,1).getContext("2d")!==null}catch{}function g(I,S){return m?new OffscreenCanvas(I,S):rl("canvas")}function b(I,S,Y){let ue=1,oe=Ze(I);if((oe.width>Y||oe.height>Y)&&(ue=Y/Math.max(oe.width,oe.height)),ue<1)if(typeof HTMLImageElement<"u"&&I instanceof HTMLImageElement||typeof HTMLCanvasElement<"u"&&I instanceof HTMLCanvasElement||typeof ImageBitmap<"u"&&I instanceof ImageBitmap||typeof VideoFrame<"u"&&I instanceof VideoFrame){let _e=Math.floor(ue*oe.width),xe=Math.floor(ue*oe.height);f===void 0&&(f=g(_e,xe));let te=S?g(_e,xe):f;return te.width=_e,te.height=xe,te.getContext("2d").drawImage(I,0,0,_e,xe),$e("WebGLRenderer: Texture has been resized from ("+oe.width+"x"+oe.height+") to ("+_e+"x"+xe+")."),te}else return"data"in I&&$e("WebGLRenderer: Image in DataTexture is too big ("+oe.width+"x"+oe.height+")."),I;return I}function T(I){return I.generateMipmaps}function v(I){n.generateMipmap(I)}function R(I){return I.isWebGLCubeRenderTarget?n.TEXTURE_CUBE_MAP:I.isWebGL3DRenderTarget?n.TEXTURE_3D:I.isWebGLArrayRenderTarget||I.isCompressedArrayTexture?n.TEXTURE_2D_ARRAY:n.TEXTURE_2D}function A(I,S,Y,ue,oe,_e=!1){if(I!==null){if(n[I]!==void 0)return n[I];$e("WebGLRenderer: Attempt to use non-existing WebGL internal format '"+I+"'")}let xe;ue&&(xe=e.get("EXT_texture_norm16"),xe||$e("WebGLRenderer: Unable to use normalized textures without EXT_texture_norm16 extension"));let te=S;if(S===n.RED&&(Y===n.FLOAT&&(te=n.R32F),Y===n.HALF_FLOAT&&(te=n.R16F),Y===n.UNSIGNED_BYTE&&(te=n.R8),Y===n.UNSIGNED_SHORT&&xe&&(te=xe.R16_EXT),Y===n.SHORT&&xe&&(te=xe.R16_SNORM_EXT)),S===n.RED_INTEGER&&(Y===n.UNSIGNED_BYTE&&(te=n.R8UI),Y===n.UNSIGNED_SHORT&&(te=n.R16UI),Y===n.UNSIGNED_INT&&(te=n.R32UI),Y===n.BYTE&&(te=n.R8I),Y===n.SHORT&&(te=n.R16I),Y===n.INT&&(te=n.R32I)),S===n.RG&&(Y===n.FLOAT&&(te=n.RG32F),Y===n.HALF_FLOAT&&(te=n.RG16F),Y===n.UNSIGNED_BYTE&&(te=n.RG8),Y===n.UNSIGNED_SHORT&&xe&&(te=xe.RG16_EXT),Y===n.SHORT&&xe&&(te=xe.RG16_SNORM_EXT)),S===n.RG_INTEGER&&(Y===n.UNSIGNED_BYTE&&(te=n.RG8UI),Y===n.UNSIGNED_SHORT&&(te=n.RG16UI),Y===n.UNSIGNED_INT&&(te=n.RG32UI),Y===n.BYTE&&(te=n.RG8I),Y===n.SHORT&&(te=n.RG16I),Y===n.INT&&(te=n.RG32I)),S===n.RGB_INTEGER&&(Y===n.UNSIGNED_BYTE&&(te=n.RGB8UI),Y===n.UNSIGNED_SHORT&&(te=n.RGB16UI),Y===n.UNSIGNED_INT&&(te=n.RGB32UI),Y===n.BYTE&&(te=n.RGB8I),Y===n.SHORT&&(te=n.RGB16I),Y===n.INT&&(te=n.RGB32I)),S===n.RGBA_INTEGER&&(Y===n.UNSIGNED_BYTE&&(te=n.RGBA8UI),Y===n.UNSIGNED_SHORT&&(te=n.RGBA16UI),Y===n.UNSIGNED_INT&&(te=n.RGBA32UI),Y===n.BYTE&&(te=n.RGBA8I),Y===n.SHORT&&(te=n.RGBA16I),Y===n.INT&&(te=n.RGBA32I)),S===n.RGB&&(Y===n.UNSIGNED_SHORT&&xe&&(te=xe.RGB16_EXT),Y===n.SHORT&&xe&&(te=xe.RGB16_SNORM_EXT),Y===n.UNSIGNED_INT_5_9_9_9_REV&&(te=n.RGB9_E5),Y===n.UNSIGNED_INT_10F_11F_11F_REV&&(te=n.R11F_G11F_B10F)),S===n.RGBA){let ie=_e?il:St.getTransfer(oe);Y===n.FLOAT&&(te=n.RGBA32F),Y===n.HALF_FLOAT&&(te=n.RGBA16F),Y===n.UNSIGNED_BYTE&&(te=ie===Lt?n.SRGB8_ALPHA8:n.RGBA8),Y===n.UNSIGNED_SHORT&&xe&&(te=xe.RGBA16_EXT),Y===n.SHORT&&xe&&(te=xe.RGBA16_SNORM_EXT),Y===n.UNSIGNED_SHORT_4_4_4_4&&(te=n.RGBA4),Y===n.UNSIGNED_SHORT_5_5_5_1&&(te=n.RGB5_A1)}return(te===n.R16F||te===n.R32F||te===n.RG16F||te===n.RG32F||te===n.RGBA16F||te===n.RGBA32F)&&e.get("EXT_color_buffer_float"),te}function _(I,S){let Y;return I?S===null||S===ji||S===Ws?Y=n.DEPTH24_STENCIL8:S===Ui?Y=n.DEPTH32F_STENCIL8:S===na&&(Y=n.DEPTH24_STENCIL8,$e("DepthTexture: 16 bit depth attachment is not supported with stencil. Using 24-bit attachment.")):S===null||S===ji||S===Ws?Y=n.DEPTH_COMPONENT24:S===Ui?Y=n.DEPTH_COMPONENT32F:S===na&&(Y=n.DEPTH_COMPONENT16),Y}function E(I,S){return T(I)===!0||I.isFramebufferTexture&&I.minFilter!==Vn&&I.minFilter!==ri?Math.log2(Math.max(S.width,S.height))+1:I.mipmaps.length>0?I.mipmaps.length:I.isCompressedTexture&&Array.isArray(I.image)?S.mipmaps.length:1}function F(I){let S=new WeakRef(I);i.get(I).__ref=S,p.add(S),x.register(I,S,S)}function N(I){let S=i.get(I).__ref;S!==void 0&&(p.delete(S),x.unregister(S))}function P(I){H(I.target)}function k(I){D(I.target)}function H(I){I.removeEventListener("dispose",P),N(I),K(I),I.isVideoTexture&&u.delete(I),I.isHTMLTexture&&h.delete(I)}function D(I){I.removeEventListener("dispose",k),N(I),ce(I)}function W(){for(let I of p){let S=I.deref();S!==void 0&&(S.isRenderTarget===!0?D(S):H(S))}p.clear(),h.clear()}function K(I){let S=i.get(I);if(S.__webglInit===void 0)return;let Y=I.source,ue=d.get(Y);if(ue){let oe=ue[S.__cacheKey];oe.usedTimes--,oe.usedTimes===0&&z(I),Object.keys(ue).length===0&&d.delete(Y)}i.remove(I)}function z(I){let S=i.get(I);n.deleteTexture(S.__webglTexture);let Y=I.source,ue=d.get(Y);delete ue[S.__cacheKey],o.memory.textures--}function ce(I){let S=i.get(I);S.__depthDisposeCallback&&S.__depthDisposeCallback();let Y=I.depthTexture;if(Y&&Y.renderTarget===I&&H(Y),I.isWebGLCubeRenderTarget)for(let oe=0;oe<6;oe++){if(Array.isArray(S.__webglFramebuffer[oe]))for(let _e=0;_e<S.__webglFramebuffer[oe].length;_e++)n.deleteFramebuffer(S.__webglFramebuffer[oe][_e]);else n.deleteFramebuffer(S.__webglFramebuffer[oe]);S.__webglDepthbuffer&&n.deleteRenderbuffer(S.__webglDepthbuffer[oe])}else{if(Array.isArray(S.__webglFramebuffer))for(let oe=0;oe<S.__webglFramebuffer.length;oe++)n.deleteFramebuffer(S.__webglFramebuffer[oe]);else n.deleteFramebuffer(S.__webglFramebuffer);if(S.__webglDepthbuffer&&n.deleteRenderbuffer(S.__webglDepthbuffer),S.__webglMultisampledFramebuffer&&n.deleteFramebuffer(S.__webglMultisampledFramebuffer),S.__webglColorRenderbuffer)for(let oe=0;oe<S.__webglColorRenderbuffer.length;oe++)S.__webglColorRenderbuffer[oe]&&n.deleteRenderbuffer(S.__webglColorRenderbuffer[oe]);S.__webglDepthRenderbuffer&&n.deleteRenderbuffer(S.__webglDepthRenderbuffer)}let ue=I.textures;for(let oe=0,_e=ue.length;oe<_e;oe++){let xe=i.get(ue[oe]);xe.__webglTexture&&(n.deleteTexture(xe.__webglTexture),o.memory.textures--),i.remove(ue[oe])}i.remove(I)}let J=0;function Q(){J=0}function re(){return J}function fe(I){J=I}function he(){let I=J;return I>=r.maxTextures&&$e("WebGLTextures: Trying to use "+(I+1)+" texture units while this GPU supports only "+r.maxTextures),J+=1,I}function ee(I){let S=[];return S.push(I.wrapS),S.push(I.wrapT),S.push(I.wrapR||0),S.push(I.magFilter),S.push(I.minFilter),S.push(I.anisotropy),S.push(I.internalFormat),S.push(I.format),S.push(I.type),S.push(I.generateMipmaps),S.push(I.mipmapsAutoUpdate),S.push(I.premultiplyAlpha),S.push(I.flipY),S.push(I.unpackAlignment),S.push(I.colorSpace),S.join()}function me(I,S){let Y=i.get(I);if(I.isVideoTexture&&Vt(I),I.isRenderTargetTexture===!1&&I.isExternalTexture!==!0&&I.version>0&&Y.__version!==I.version){let ue=I.image;if(ue===null)$e("WebGLRenderer: Texture marked for update but no image data found.");else if(ue.complete===!1)$e("WebGLRenderer: Texture marked for update but image is incomplete");else{Xt(Y,I,S);return}}else I.isExternalTexture&&(Y.__webglTexture=I.sourceTexture?I.sourceTexture:null);t.bindTexture(n.TEXTURE_2D,Y.__webglTexture,n.TEXTURE0+S)}function ye(I,S){let Y=i.get(I);if(I.isRenderTargetTexture===!1&&I.version>0&&Y.__version!==I.version){Xt(Y,I,S);return}else I.isExternalTexture&&(Y.__webglTexture=I.sourceTexture?I.sourceTexture:null);t.bindTexture(n.TEXTURE_2D_ARRAY,Y.__webglTexture,n.TEXTURE0+S)}function Ae(I,S){let Y=i.get(I);if(I.isRenderTargetTexture===!1&&I.version>0&&Y.__version!==I.version){Xt(Y,I,S);return}t.bindTexture(n.TEXTURE_3D,Y.__webglTexture,n.TEXTURE0+S)}function Se(I,S){let Y=i.get(I);if(I.version>0&&Y.__version!==I.version){mn(Y,I,S);return}t.bindTexture(n.TEXTURE_CUBE_MAP,Y.__webglTexture,n.TEXTURE0+S)}let Xe={[Nu]:n.REPEAT,[mr]:n.CLAMP_TO_EDGE,[Pu]:n.MIRRORED_REPEAT},ot={[Vn]:n.NEAREST,[Db]:n.NEAREST_MIPMAP_NEAREST,[Al]:n.NEAREST_MIPMAP_LINEAR,[ri]:n.LINEAR,[lh]:n.LINEAR_MIPMAP_NEAREST,[Hr]:n.LINEAR_MIPMAP_LINEAR},ze={[Bb]:n.NEVER,[am]:n.ALWAYS,[kb]:n.LESS,[sm]:n.LEQUAL,[Vb]:n.EQUAL,[om]:n.GEQUAL,[Gb]:n.GREATER,[zb]:n.NOTEQUAL};function ft(I,S){if(S.type===Ui&&e.has("OES_texture_float_linear")===!1&&(S.magFilter===ri||S.magFilter===lh||S.magFilter===Al||S.magFilter===Hr||S.minFilter===ri||S.minFilter===lh||S.minFilter===Al||S.minFilter===Hr)&&$e("WebGLRenderer: Unable to use linear filtering with floating point textures. OES_texture_float_linear not supported on this device."),n.texParameteri(I,n.TEXTURE_WRAP_S,Xe[S.wrapS]),n.texParameteri(I,n.TEXTURE_WRAP_T,Xe[S.wrapT]),(I===n.TEXTURE_3D||I===n.TEXTURE_2D_ARRAY)&&n.texParameteri(I,n.TEXTURE_WRAP_R,Xe[S.wrapR]),n.texParameteri(I,n.TEXTURE_MAG_FILTER,ot[S.magFilter]),n.texParameteri(I,n.TEXTURE_MIN_FILTER,ot[S.minFilter]),S.compareFunction&&(n.texParameteri(I,n.TEXTURE_COMPARE_MODE,n.COMPARE_REF_TO_TEXTURE),n.texParameteri(I,n.TEXTURE_COMPARE_FUNC,ze[S.compareFunction])),e.has("EXT_texture_filter_anisotropic")===!0){if(S.magFilter===Vn||S.minFilter!==Al&&S.minFilter!==Hr||S.type===Ui&&e.has("OES_texture_float_linear")===!1)return;if(S.anisotropy>1||i.get(S).__currentAnisotropy){let Y=e.get("EXT_texture_filter_anisotropic");n.texParameterf(I,Y.TEXTURE_MAX_ANISOTROPY_EXT,Math.min(S.anisotropy,r.getMaxAnisotropy())),i.get(S).__currentAnisotropy=S.anisotropy}}}function ct(I,S){let Y=!1;I.__webglInit===void 0&&(I.__webglInit=!0,S.addEventListener("dispose",P),F(S));let ue=S.source,oe=d.get(ue);oe===void 0&&(oe={},d.set(ue,oe));let _e=ee(S);if(_e!==I.__cacheKey){oe[_e]===void 0&&(oe[_e]={texture:n.createTexture(),usedTimes:0},o.memory.textures++,Y=!0),oe[_e].usedTimes++;let xe=oe[I.__cacheKey];xe!==void 0&&(oe[I.__cacheKey].usedTimes--,xe.usedTimes===0&&z(S)),I.__cacheKey=_e,I.__webglTexture=oe[_e].texture}return Y}function rt(I,S,Y){return Math.floor(Math.floor(I/Y)/S)}function Qt(I,S,Y,ue){let _e=I.updateRanges;if(_e.length===0)t.texSubImage2D(n.TEXTURE_2D,0,0,0,S.width,S.height,Y,ue,S.data);else{_e.sort((U,se)=>U.start-se.start);let xe=0;for(let U=1;U<_e.length;U++){let se=_e[xe],ne=_e[U],Me=se.start+se.count,ge=rt(ne.start,S.width,4),ve=rt(se.start,S.width,4);ne.start<=Me+1&&ge===ve&&rt(ne.start+ne.count-1,S.width,4)===ge?se.count=Math.max(se.count,ne.start+ne.count-se.start):(++xe,_e[xe]=ne)}_e.length=xe+1;let te=t.getParameter(n.UNPACK_ROW_LENGTH),ie=t.getParameter(n.UNPACK_SKIP_PIXELS),pe=t.getParameter(n.UNPACK_SKIP_ROWS);t.pixelStorei(n.UNPACK_ROW_LENGTH,S.width);for(let U=0,se=_e.length;U<se;U++){let ne=_e[U],Me=Math.floor(ne.start/4),ge=Math.ceil(ne.count/4),ve=Me%S.width,He=Math.floor(Me/S.width),je=ge,le=1;t.pixelStorei(n.UNPACK_SKIP_PIXELS,ve),t.pixelStorei(n.UNPACK_SKIP_ROWS,He),t.texSubImage2D(n.TEXTURE_2D,0,ve,He,je,le,Y,ue,S.data)}I.clearUpdateRanges(),t.pixelStorei(n.UNPACK_ROW_LENGTH,te),t.pixelStorei(n.UNPACK_SKIP_PIXELS,ie),t.pixelStorei(n.UNPACK_SKIP_ROWS,pe)}}function Xt(I,S,Y){let ue=n.TEXTURE_2D;(S.isDataArrayTexture||S.isCompressedArrayTexture)&&(ue=n.TEXTURE_2D_ARRAY),S.isData3DTexture&&(ue=n.TEXTURE_3D);let oe=ct(I,S),_e=S.source;t.bindTexture(ue,I.__webglTexture,n.TEXTURE0+Y);let xe=i.get(_e);if(_e.version!==xe.__version||oe===!0){if(t.activeTexture(n.TEXTURE0+Y),(typeof ImageBitmap<"u"&&S.image instanceof ImageBitmap)===!1){let le=St.getPrimaries(St.workingColorSpace),Be=S.colorSpace===Xr?null:St.getPrimaries(S.colorSpace),Qe=S.colorSpace===Xr||le===Be?n.NONE:n.BROWSER_DEFAULT_WEBGL;t.pixelStorei(n.UNPACK_FLIP_Y_WEBGL,S.flipY),t.pixelStorei(n.UNPACK_PREMULTIPLY_ALPHA_WEBGL,S.premultiplyAlpha),t.pixelStorei(n.UNPACK_COLORSPACE_CONVERSION_WEBGL,Qe)}t.pixelStorei(n.UNPACK_ALIGNMENT,S.unpackAlignment);let ie=b(S.image,!1,r.maxTextureSize);ie=Ge(S,ie);let pe=s.convert(S.format,S.colorSpace),U=s.convert(S.type),se=A(S.internalFormat,pe,U,S.normalized,S.colorSpace,S.isVideoTexture);ft(ue,S);let ne,Me=S.mipmaps,ge=S.isVideoTexture!==!0,ve=xe.__version===void 0||oe===!0,He=_e.dataReady,je=E(S,ie);if(S.isDepthTexture)se=_(S.format===Wr,S.type),ve&&(ge?t.texStorage2D(n.TEXTURE_2D,1,se,ie.width,ie.height):t.texImage2D(n.TEXTURE_2D,0,se,ie.width,ie.height,0,pe,U,null));else if(S.isDataTexture)if(Me.length>0){ge&&ve&&t.texStorage2D(n.TEXTURE_2D,je,se,Me[0].width,Me[0].height);for(let le=0,Be=Me.length;le<Be;le++)ne=Me[le],ge?He&&t.texSubImage2D(n.TEXTURE_2D,le,0,0,ne.width,ne.height,pe,U,ne.data):t.texImage2D(n.TEXTURE_2D,le,se,ne.width,ne.height,0,pe,U,ne.data);S.generateMipmaps=!1}else ge?(ve&&t.texStorage2D(n.TEXTURE_2D,je,se,ie.width,ie.height),He&&Qt(S,ie,pe,U)):t.texImage2D(n.TEXTURE_2D,0,se,ie.width,ie.height,0,pe,U,ie.data);else if(S.isCompressedTexture)if(S.isCompressedArrayTexture){ge&&ve&&t.texStorage3D(n.TEXTURE_2D_ARRAY,je,se,Me[0].width,Me[0].height,ie.depth);for(let le=0,Be=Me.length;le<Be;le++)if(ne=Me[le],S.format!==er)if(pe!==null)if(ge){if(He)if(S.layerUpdates.size>0){let Qe=gm(ne.width,ne.height,S.format,S.type);for(let Re of S.layerUpdates){let lt=ne.data.subarray(Re*Qe/ne.data.BYTES_PER_ELEMENT,(Re+1)*Qe/ne.data.BYTES_PER_ELEMENT);t.compressedTexSubImage3D(n.TEXTURE_2D_ARRAY,le,0,0,Re,ne.width,ne.height,1,pe,lt)}}else t.compressedTexSubImage3D(n.TEXTURE_2D_ARRAY,le,0,0,0,ne.width,ne.height,ie.depth,pe,ne.data)}else t.compressedTexImage3D(n.TEXTURE_2D_ARRAY,le,se,ne.width,ne.height,ie.depth,0,ne.data,0,0);else $e("WebGLRenderer: Attempt to load unsupported compressed texture format in .uploadTexture()");else ge?He&&t.texSubImage3D(n.TEXTURE_2D_ARRAY,le,0,0,0,ne.width,ne.height,ie.depth,pe,U,ne.data):t.texImage3D(n.TEXTURE_2D_ARRAY,le,se,ne.width,ne.height,ie.depth,0,pe,U,ne.data);S.layerUpdates.size>0&&S.clearLayerUpdates()}else{ge&&ve&&t.texStorage2D(n.TEXTURE_2D,je,se,Me[0].width,Me[0].height);for(let le=0,Be=Me.length;le<Be;le++)ne=Me[le],S.format!==er?pe!==null?ge?He&&t.compressedTexSubImage2D(n.TEXTURE_2D,le,0,0,ne.width,ne.height,pe,ne.data):t.compressedTexImage2D(n.TEXTURE_2D,le,se,ne.width,ne.height,0,ne.data):$e("WebGLRenderer: Attempt to load unsupported compressed texture format in .uploadTexture()"):ge?He&&t.texSubImage2D(n.TEXTURE_2D,le,0,0,ne.width,ne.height,pe,U,ne.data):t.texImage2D(n.TEXTURE_2D,le,se,ne.width,ne.height,0,pe,U,ne.data)}else if(S.isDataArrayTexture)if(ge){if(ve&&t.texStorage3D(n.TEXTURE_2D_ARRAY,je,se,ie.width,ie.height,ie.depth),He)if(S.layerUpdates.size>0){let le=gm(ie.width,ie.height,S.format,S.type);for(let Be of S.layerUpdates){let Qe=ie.data.subarray(Be*le/ie.data.BYTES_PER_ELEMENT,(Be+1)*le/ie.data.BYTES_PER_ELEMENT);t.texSubImage3D(n.TEXTURE_2D_ARRAY,0,0,0,Be,ie.width,ie.height,1,pe,U,Qe)}S.clearLayerUpdates()}else t.texSubImage3D(n.TEXTURE_2D_ARRAY,0,0,0,0,ie.width,ie.height,ie.depth,pe,U,ie.data)}else t.texImage3D(n.TEXTURE_2D_ARRAY,0,se,ie.width,ie.height,ie.depth,0,pe,U,ie.data);else if(S.isData3DTexture)ge?(ve&&t.texStorage3D(n.TEXTURE_3D,je,se,ie.width,ie.height,ie.depth),He&&t.texSubImage3D(n.TEXTURE_3D,0,0,0,0,ie.width,ie.height,ie.depth,pe,U,ie.data)):t.texImage3D(n.TEXTURE_3D,0,se,ie.width,ie.height,ie.depth,0,pe,U,ie.data);else if(S.isFramebufferTexture){if(ve)if(ge)t.texStorage2D(n.TEXTURE_2D,je,se,ie.width,ie.height);else{let le=ie.width,Be=ie.height;for(let Qe=0;Qe<je;Qe++)t.texImage2D(n.TEXTURE_2D,Qe,se,le,Be,0,pe,U,null),le>>=1,Be>>=1}}else if(S.isHTMLTexture){if("texElementImage2D"in n){let le=n.canvas;if(le.hasAttribute("layoutsubtree")||le.setAttribute("layoutsubtree","true"),ie.parentNode!==le){le.appendChild(ie),h.add(S),le.onpaint=Be=>{let Qe=Be.changedElements;for(let Re of h)Qe.includes(Re.image)&&(Re.needsUpdate=!0)},le.requestPaint();return}if(n.texElementImage2D.length===3)n.texElementImage2D(n.TEXTURE_2D,n.RGBA8,ie);else{let Qe=n.RGBA,Re=n.RGBA,lt=n.UNSIGNED_BYTE;n.texElementImage2D(n.TEXTURE_2D,0,Qe,Re,lt,ie)}n.texParameteri(n.TEXTURE_2D,n.TEXTURE_MIN_FILTER,n.LINEAR),n.texParameteri(n.TEXTURE_2D,n.TEXTURE_WRAP_S,n.CLAMP_TO_EDGE),n.texParameteri(n.TEXTURE_2D,n.TEXTURE_WRAP_T,n.CLAMP_TO_EDGE)}}else if(Me.length>0){if(ge&&ve){let le=Ze(Me[0]);t.texStorage2D(n.TEXTURE_2D,je,se,le.width,le.height)}for(let le=0,Be=Me.length;le<Be;le++)ne=Me[le],ge?He&&t.texSubImage2D(n.TEXTURE_2D,le,0,0,pe,U,ne):t.texImage2D(n.TEXTURE_2D,le,se,pe,U,ne);S.generateMipmaps=!1}else if(ge){if(ve){let le=Ze(ie);t.texStorage2D(n.TEXTURE_2D,je,se,le.width,le.height)}He&&t.texSubImage2D(n.TEXTURE_2D,0,0,0,pe,U,ie)}else t.texImage2D(n.TEXTURE_2D,0,se,pe,U,ie);T(S)&&S.mipmapsAutoUpdate===!0&&v(ue),xe.__version=_e.version,S.onUpdate&&S.onUpdate(S)}I.__version=S.version}function mn(I,S,Y){if(S.image.length!==6)return;let ue=ct(I,S),oe=S.source;t.bindTexture(n.TEXTURE_CUBE_MAP,I.__webglTexture,n.TEXTURE0+Y);let _e=i.get(oe);if(oe.version!==_e.__version||ue===!0){t.activeTexture(n.TEXTURE0+Y);let xe=St.getPrimaries(St.workingColorSpace),te=S.colorSpace===Xr?null:St.getPrimaries(S.colorSpace),ie=S.colorSpace===Xr||xe===te?n.NONE:n.BROWSER_DEFAULT_WEBGL;t.pixelStorei(n.UNPACK_FLIP_Y_WEBGL,S.flipY),t.pixelStorei(n.UNPACK_PREMULTIPLY_ALPHA_WEBGL,S.premultiplyAlpha),t.pixelStorei(n.UNPACK_ALIGNMENT,S.unpackAlignment),t.pixelStorei(n.UNPACK_COLORSPACE_CONVERSION_WEBGL,ie);let pe=S.isCompressedTexture||S.image[0].isCompressedTexture,U=S.image[0]&&S.image[0].isDataTexture,se=[];for(let Re=0;Re<6;Re++)!pe&&!U?se[Re]=b(S.image[Re],!0,r.maxCubemapSize):se[Re]=U?S.image[Re].image:S.image[Re],se[Re]=Ge(S,se[Re]);let ne=se[0],Me=s.convert(S.format,S.colorSpace),ge=s.convert(S.type),ve=A(S.internalFormat,Me,ge,S.normalized,S.colorSpace),He=S.isVideoTexture!==!0,je=_e.__version===void 0||ue===!0,le=oe.dataReady,Be=E(S,ne);ft(n.TEXTURE_CUBE_MAP,S);let Qe;if(S.isDepthTexture){if(ve=_(S.format===Wr,S.type),je)if(He)t.texStorage2D(n.TEXTURE_CUBE_MAP,1,ve,ne.width,ne.height);else for(let Re=0;Re<6;Re++)t.texImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Re,0,ve,ne.width,ne.height,0,Me,ge,null)}else if(pe){He&&je&&t.texStorage2D(n.TEXTURE_CUBE_MAP,Be,ve,ne.width,ne.height);for(let Re=0;Re<6;Re++){Qe=se[Re].mipmaps;for(let lt=0;lt<Qe.length;lt++){let Yt=Qe[lt];S.format!==er?Me!==null?He?le&&t.compressedTexSubImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Re,lt,0,0,Yt.width,Yt.height,Me,Yt.data):t.compressedTexImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Re,lt,ve,Yt.width,Yt.height,0,Yt.data):$e("WebGLRenderer: Attempt to load unsupported compressed texture format in .setTextureCube()"):He?le&&t.texSubImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Re,lt,0,0,Yt.width,Yt.height,Me,ge,Yt.data):t.texImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Re,lt,ve,Yt.width,Yt.height,0,Me,ge,Yt.data)}}}else{if(Qe=S.mipmaps,He&&je){Qe.length>0&&Be++;let Re=Ze(se[0]);t.texStorage2D(n.TEXTURE_CUBE_MAP,Be,ve,Re.width,Re.height)}for(let Re=0;Re<6;Re++)if(U){He?le&&t.texSubImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Re,0,0,0,se[Re].width,se[Re].height,Me,ge,se[Re].data):t.texImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Re,0,ve,se[Re].width,se[Re].height,0,Me,ge,se[Re].data);for(let lt=0;lt<Qe.length;lt++){let Jn=Qe[lt].image[Re].image;He?le&&t.texSubImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Re,lt+1,0,0,Jn.width,Jn.height,Me,ge,Jn.data):t.texImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Re,lt+1,ve,Jn.width,Jn.height,0,Me,ge,Jn.data)}}else{He?le&&t.texSubImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Re,0,0,0,Me,ge,se[Re]):t.texImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Re,0,ve,Me,ge,se[Re]);for(let lt=0;lt<Qe.length;lt++){let Yt=Qe[lt];He?le&&t.texSubImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Re,lt+1,0,0,Me,ge,Yt.image[Re]):t.texImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Re,lt+1,ve,Me,ge,Yt.image[Re])}}}T(S)&&S.mipmapsAutoUpdate===!0&&v(n.TEXTURE_CUBE_MAP),_e.__version=oe.version,S.onUpdate&&S.onUpdate(S)}I.__version=S.version}function Ot(I,S,Y,ue,oe,_e){let xe=s.convert(Y.format,Y.colorSpace),te=s.convert(Y.type),ie=A(Y.internalFormat,xe,te,Y.normalized,Y.colorSpace),pe=i.get(S),U=i.get(Y);if(U.__renderTarget=S,!pe.__hasExternalTextures){let se=Math.max(1,S.width>>_e),ne=Math.max(1,S.height>>_e);oe===n.TEXTURE_3D||oe===n.TEXTURE_2D_ARRAY?t.texImage3D(oe,_e,ie,se,ne,S.depth,0,xe,te,null):t.texImage2D(oe,_e,ie,se,ne,0,xe,te,null)}t.bindFramebuffer(n.FRAMEBUFFER,I),Ee(S)?a.framebufferTexture2DMultisampleEXT(n.FRAMEBUFFER,ue,oe,U.__webglTexture,0,at(S)):(oe===n.TEXTURE_2D||oe>=n.TEXTURE_CUBE_MAP_POSITIVE_X&&oe<=n.TEXTURE_CUBE_MAP_NEGATIVE_Z)&&n.framebufferTexture2D(n.FRAMEBUFFER,ue,oe,U.__webglTexture,_e),t.bindFramebuffer(n.FRAMEBUFFER,null)}function Ln(I,S,Y){if(n.bindRenderbuffer(n.RENDERBUFFER,I),S.depthBuffer){let ue=S.depthTexture,oe=ue&&ue.isDepthTexture?ue.type:null,_e=_(S.stencilBuffer,oe),xe=S.stencilBuffer?n.DEPTH_STENCIL_ATTACHMENT:n.DEPTH_ATTACHMENT;Ee(S)?a.renderbufferStorageMultisampleEXT(n.RENDERBUFFER,at(S),_e,S.width,S.height):Y?n.renderbufferStorageMultisample(n.RENDERBUFFER,at(S),_e,S.width,S.height):n.renderbufferStorage(n.RENDERBUFFER,_e,S.width,S.height),n.framebufferRenderbuffer(n.FRAMEBUFFER,xe,n.RENDERBUFFER,I)}else{let ue=S.textures;for(let oe=0;oe<ue.length;oe++){let _e=ue[oe],xe=s.convert(_e.format,_e.colorSpace),te=s.convert(_e.type),ie=A(_e.internalFormat,xe,te,_e.normalized,_e.colorSpace);Ee(S)?a.renderbufferStorageMultisampleEXT(n.RENDERBUFFER,at(S),ie,S.width,S.height):Y?n.renderbufferStorageMultisample(n.RENDERBUFFER,at(S),ie,S.width,S.height):n.renderbufferStorage(n.RENDERBUFFER,ie,S.width,S.height)}}n.bindRenderbuffer(n.RENDERBUFFER,null)}function wt(I,S,Y){let ue=S.isWebGLCubeRenderTarget===!0;if(t.bindFramebuffer(n.FRAMEBUFFER,I),!(S.depthTexture&&S.depthTexture.isDepthTexture))throw new Error("THREE.WebGLTextures: renderTarget.depthTexture must be an instance of THREE.DepthTexture.");let oe=i.get(S.depthTexture);oe.__renderTarget=S;let _e=ue?S.depthTexture.image[0]:S.depthTexture.image;(!oe.__webglTexture||_e.width!==S.width||_e.height!==S.height)&&(_e.width=S.width,_e.height=S.height,S.depthTexture.needsUpdate=!0),ue?Se(S.depthTexture,0):me(S.depthTexture,0);let xe=oe.__webglTexture,te=at(S),ie=ue?n.TEXTURE_CUBE_MAP_POSITIVE_X+Y:n.TEXTURE_2D,pe=S.depthTexture.format===Wr?n.DEPTH_STENCIL_ATTACHMENT:n.DEPTH_ATTACHMENT;if(S.depthTexture.format===kr)Ee(S)?a.framebufferTexture2DMultisampleEXT(n.FRAMEBUFFER,pe,ie,xe,0,te):n.framebufferTexture2D(n.FRAMEBUFFER,pe,ie,xe,0);else if(S.depthTexture.format===Wr)Ee(S)?a.framebufferTexture2DMultisampleEXT(n.FRAMEBUFFER,pe,ie,xe,0,te):n.framebufferTexture2D(n.FRAMEBUFFER,pe,ie,xe,0);else throw new Error("THREE.WebGLTextures: Unknown depthTexture format.")}function Mn(I){let S=i.get(I),Y=I.isWebGLCubeRenderTarget===!0;if(S.__boundDepthTexture!==I.depthTexture){let ue=I.depthTexture;if(S.__depthDisposeCallback&&S.__depthDisposeCallback(),ue){let oe=()=>{delete S.__boundDepthTexture,delete S.__depthDisposeCallback,ue.removeEventListener("dispose",oe)};ue.addEventListener("dispose",oe),S.__depthDisposeCallback=oe}S.__boundDepthTexture=ue}if(I.depthTexture&&!S.__autoAllocateDepthBuffer)if(Y)for(let ue=0;ue<6;ue++)wt(S.__webglFramebuffer[ue],I,ue);else I.texture.mipmaps.length>0?wt(S.__webglFramebuffer[0],I,0):wt(S.__webglFramebuffer,I,0);else if(Y){S.__webglDepthbuffer=[];for(let ue=0;ue<6;ue++)if(t.bindFramebuffer(n.FRAMEBUFFER,S.__webglFramebuffer[ue]),S.__webglDepthbuffer[ue]===void 0)S.__webglDepthbuffer[ue]=n.createRenderbuffer(),Ln(S.__webglDepthbuffer[ue],I,!1);else{let oe=I.stencilBuffer?n.DEPTH_STENCIL_ATTACHMENT:n.DEPTH_ATTACHMENT,_e=S.__webglDepthbuffer[ue];n.bindRenderbuffer(n.RENDERBUFFER,_e),n.framebufferRenderbuffer(n.FRAMEBUFFER,oe,n.RENDERBUFFER,_e)}}else if(I.texture.mipmaps.length>0?t.bindFramebuffer(n.FRAMEBUFFER,S.__webglFramebuffer[0]):t.bindFramebuffer(n.FRAMEBUFFER,S.__webglFramebuffer),S.__webglDepthbuffer===void 0)S.__webglDepthbuffer=n.createRenderbuffer(),Ln(S.__webglDepthbuffer,I,!1);else{let oe=I.stencilBuffer?n.DEPTH_STENCIL_ATTACHMENT:n.DEPTH_ATTACHMENT,_e=S.__webglDepthbuffer;n.bindRenderbuffer(n.RENDERBUFFER,_e),n.framebufferRenderbuffer(n.FRAMEBUFFER,oe,n.RENDERBUFFER,_e)}t.bindFramebuffer(n.FRAMEBUFFER,null)}function sn(I,S,Y){let ue=i.get(I);S!==void 0&&Ot(ue.__webglFramebuffer,I,I.texture,n.COLOR_ATTACHMENT0,n.TEXTURE_2D,0),Y!==void 0&&Mn(I)}function gn(I){let S=I.texture,Y=i.get(I),ue=i.get(S);I.addEventListener("dispose",k),F(I);let oe=I.textures,_e=I.isWebGLCubeRenderTarget===!0,xe=oe.length>1;if(xe||(ue.__webglTexture===void 0&&(ue.__webglTexture=n.createTexture()),ue.__version=S.version,o.memory.textures++),_e){Y.__webglFramebuffer=[];for(let te=0;te<6;te++)if(S.mipmaps.length>0){Y.__webglFramebuffer[te]=[];for(let ie=0;ie<S.mipmaps.length;ie++)Y.__webglFramebuffer[te][ie]=n.createFramebuffer()}else Y.__webglFramebuffer[te]=n.createFramebuffer()}else{if(S.mipmaps.length>0){Y.__webglFramebuffer=[];for(let te=0;te<S.mipmaps.length;te++)Y.__webglFramebuffer[te]=n.createFramebuffer()}else Y.__webglFramebuffer=n.createFramebuffer();if(xe)for(let te=0,ie=oe.length;te<ie;te++){let pe=i.get(oe[te]);pe.__webglTexture===void 0&&(pe.__webglTexture=n.createTexture(),o.memory.textures++)}if(I.samples>0&&Ee(I)===!1){Y.__webglMultisampledFramebuffer=n.createFramebuffer(),Y.__webglColorRenderbuffer=[],t.bindFramebuffer(n.FRAMEBUFFER,Y.__webglMultisampledFramebuffer);for(let te=0;te<oe.length;te++){let ie=oe[te];Y.__webglColorRenderbuffer[te]=n.createRenderbuffer(),n.bindRenderbuffer(n.RENDERBUFFER,Y.__webglColorRenderbuffer[te]);let pe=s.convert(ie.format,ie.colorSpace),U=s.convert(ie.type),se=A(ie.internalFormat,pe,U,ie.normalized,ie.colorSpace,I.isXRRenderTarget===!0),ne=at(I);n.renderbufferStorageMultisample(n.RENDERBUFFER,ne,se,I.width,I.height),n.framebufferRenderbuffer(n.FRAMEBUFFER,n.COLOR_ATTACHMENT0+te,n.RENDERBUFFER,Y.__webglColorRenderbuffer[te])}n.bindRenderbuffer(n.RENDERBUFFER,null),I.depthBuffer&&(Y.__webglDepthRenderbuffer=n.createRenderbuffer(),Ln(Y.__webglDepthRenderbuffer,I,!0)),t.bindFramebuffer(n.FRAMEBUFFER,null)}}if(_e){t.bindTexture(n.TEXTURE_CUBE_MAP,ue.__webglTexture),ft(n.TEXTURE_CUBE_MAP,S);for(let te=0;te<6;te++)if(S.mipmaps.length>0)for(let ie=0;ie<S.mipmaps.length;ie++)Ot(Y.__webglFramebuffer[te][ie],I,S,n.COLOR_ATTACHMENT0,n.TEXTURE_CUBE_MAP_POSITIVE_X+te,ie);else Ot(Y.__webglFramebuffer[te],I,S,n.COLOR_ATTACHMENT0,n.TEXTURE_CUBE_MAP_POSITIVE_X+te,0);T(S)?v(n.TEXTURE_CUBE_MAP):S.mipmaps.length>0&&n.texParameteri(n.TEXTURE_CUBE_MAP,n.TEXTURE_MAX_LEVEL,S.mipmaps.length-1),t.unbindTexture()}else if(xe){for(let te=0,ie=oe.length;te<ie;te++){let pe=oe[te],U=i.get(pe),se=n.TEXTURE_2D;(I.isWebGL3DRenderTarget||I.isWebGLArrayRenderTarget)&&(se=I.isWebGL3DRenderTarget?n.TEXTURE_3D:n.TEXTURE_2D_ARRAY),t.bindTexture(se,U.__webglTexture),ft(se,pe),Ot(Y.__webglFramebuffer,I,pe,n.COLOR_ATTACHMENT0+te,se,0),T(pe)&&v(se)}t.unbindTexture()}else{let te=n.TEXTURE_2D;if((I.isWebGL3DRenderTarget||I.isWebGLArrayRenderTarget)&&(te=I.isWebGL3DRenderTarget?n.TEXTURE_3D:n.TEXTURE_2D_ARRAY),t.bindTexture(te,ue.__webglTexture),ft(te,S),S.mipmaps.length>0)for(let ie=0;ie<S.mipmaps.length;ie++)Ot(Y.__webglFramebuffer[ie],I,S,n.COLOR_ATTACHMENT0,te,ie);else Ot(Y.__webglFramebuffer,I,S,n.COLOR_ATTACHMENT0,te,0);T(S)?v(te):S.mipmaps.length>0&&n.texParameteri(te,n.TEXTURE_MAX_LEVEL,S.mipmaps.length-1),t.unbindTexture()}I.depthBuffer&&Mn(I)}function O(I){let S=I.textures;for(let Y=0,ue=S.length;Y<ue;Y++){let oe=S[Y];if(T(oe)&&oe.mipmapsAutoUpdate===!0){let _e=R(I),xe=i.get(oe).__webglTexture;t.bindTexture(_e,xe),v(_e),t.unbindTexture()}}}let Ie=[];function qe(I){if(I.samples>0){if(Ee(I)===!1){let S=I.textures,Y=I.width,ue=I.height,oe=n.COLOR_BUFFER_BIT,_e=I.stencilBuffer?n.DEPTH_STENCIL_ATTACHMENT:n.DEPTH_ATTACHMENT,xe=i.get(I),te=S.length>1;if(te)for(let pe=0;pe<S.length;pe++)t.bindFramebuffer(n.FRAMEBUFFER,xe.__webglMultisampledFramebuffer),n.framebufferRenderbuffer(n.FRAMEBUFFER,n.COLOR_ATTACHMENT0+pe,n.RENDERBUFFER,null),t.bindFramebuffer(n.FRAMEBUFFER,xe.__webglFramebuffer),n.framebufferTexture2D(n.DRAW_FRAMEBUFFER,n.COLOR_ATTACHMENT0+pe,n.TEXTURE_2D,null,0);t.bindFramebuffer(n.READ_FRAMEBUFFER,xe.__webglMultisampledFramebuffer),I.texture.mipmaps.length>0?t.bindFramebuffer(n.DRAW_FRAMEBUFFER,xe.__webglFramebuffer[0]):t.bindFramebuffer(n.DRAW_FRAMEBUFFER,xe.__webglFramebuffer);for(let pe=0;pe<S.length;pe++){if(I.resolveDepthBuffer&&(I.depthBuffer&&(oe|=n.DEPTH_BUFFER_BIT),I.stencilBuffer&&I.resolveStencilBuffer&&(oe|=n.STENCIL_BUFFER_BIT)),te){n.framebufferRenderbuffer(n.READ_FRAMEBUFFER,n.COLOR_ATTACHMENT0,n.RENDERBUFFER,xe.__webglColorRenderbuffer[pe]);let U=i.get(S[pe]).__webglTexture;n.framebufferTexture2D(n.DRAW_FRAMEBUFFER,n.COLOR_ATTACHMENT0,n.TEXTURE_2D,U,0)}n.blitFramebuffer(0,0,Y,ue,0,0,Y,ue,oe,n.NEAREST),l===!0&&(Ie.length=0,Ie.push(n.COLOR_ATTACHMENT0+pe),I.depthBuffer&&I.storeMultisampledDepthBuffer===!1&&Ie.push(_e),n.invalidateFramebuffer(n.READ_FRAMEBUFFER,Ie))}if(t.bindFramebuffer(n.READ_FRAMEBUFFER,null),t.bindFramebuffer(n.DRAW_FRAMEBUFFER,null),te)for(let pe=0;pe<S.length;pe++){t.bindFramebuffer(n.FRAMEBUFFER,xe.__webglMultisampledFramebuffer),n.framebufferRenderbuffer(n.FRAMEBUFFER,n.COLOR_ATTACHMENT0+pe,n.RENDERBUFFER,xe.__webglColorRenderbuffer[pe]);let U=i.get(S[pe]).__webglTexture;t.bindFramebuffer(n.FRAMEBUFFER,xe.__webglFramebuffer),n.framebufferTexture2D(n.DRAW_FRAMEBUFFER,n.COLOR_ATTACHMENT0+pe,n.TEXTURE_2D,U,0)}t.bindFramebuffer(n.DRAW_FRAMEBUFFER,xe.__webglMultisampledFramebuffer)}else if(I.depthBuffer&&I.storeMultisampledDepthBuffer===!1&&l){let S=I.stencilBuffer?n.DEPTH_STENCIL_ATTACHMENT:n.DEPTH_ATTACHMENT;n.invalidateFramebuffer(n.DRAW_FRAMEBUFFER,[S])}}}function at(I){return Math.min(r.maxSamples,I.samples)}function Ee(I){let S=i.get(I);return I.samples>0&&e.has("WEBGL_multisampled_render_to_texture")===!0&&S.__useRenderToTexture!==!1}function Vt(I){let S=o.render.frame;u.get(I)!==S&&(u.set(I,S),I.update())}function Ge(I,S){let Y=I.colorSpace,ue=I.format,oe=I.type;return I.isCompressedTexture===!0||I.isVideoTexture===!0||Y!==nl&&Y!==Xr&&(St.getTransfer(Y)===Lt?(ue!==er||oe!==li)&&$e("WebGLTextures: sRGB encoded textures have to use RGBAFormat and UnsignedByteType."):et("WebGLTextures: Unsupported texture color space:",Y)),S}function Ze(I){return typeof HTMLImageElement<"u"&&I instanceof HTMLImageElement?(c.width=I.naturalWidth||I.width,c.height=I.naturalHeight||I.height):typeof VideoFrame<"u"&&I instanceof VideoFrame?(c.width=I.displayWidth,c.height=I.displayHeight):(c.width=I.width,c.height=I.height),c}this.allocateTextureUnit=he,this.resetTextureUnits=Q,this.getTextureUnits=re,this.setTextureUnits=fe,this.setTexture2D=me,this.setTexture2DArray=ye,this.setTexture3D=Ae,this.setTextureCube=Se,this.rebindTextures=sn,this.setupRenderTarget=gn,this.updateRenderTargetMipmap=O,this.updateMultisampleRenderTarget=qe,this.setupDepthRenderbuffer=Mn,this.setupFrameBufferTexture=Ot,this.useMultisampledRTT=Ee,this.dispose=W}function NN(n,e){function t(i,r=Xr){let s,o=St.getTransfer(r);if(i===li)return n.UNSIGNED_BYTE;if(i===uh)return n.UNSIGNED_SHORT_4_4_4_4;if(i===hh)return n.UNSIGNED_SHORT_5_5_5_1;if(i===tm)return n.UNSIGNED_INT_5_9_9_9_REV;if(i===nm)return n.UNSIGNED_INT_10F_11F_11F_REV;if(i===Qp)return n.BYTE;if(i===em)return n.SHORT;if(i===na)return n.UNSIGNED_SHORT;if(i===ch)return n.INT;if(i===ji)return n.UNSIGNED_INT;if(i===Ui)return n.FLOAT;if(i===Qi)return n.HALF_FLOAT;if(i===im)return n.ALPHA;if(i===rm)return n.RGB;if(i===er)return n.RGBA;if(i===kr)return n.DEPTH_COMPONENT;if(i===Wr)return n.DEPTH_STENCIL;if(i===fh)return n.RED;if(i===dh)return n.RED_INTEGER;if(i===bs)return n.RG;if(i===ph)return n.RG_INTEGER;if(i===mh)return n.RGBA_INTEGER;if(i===Rl||i===Il||i===Cl||i===Nl)if(o===Lt)if(s=e.get("WEBGL_compressed_texture_s3tc_srgb"),s!==null){if(i===Rl)return s.COMPRESSED_SRGB_S3TC_DXT1_EXT;if(i===Il)return s.COMPRESSED_SRGB_ALPHA_S3TC_DXT1_EXT;if(i===Cl)return s.COMPRESSED_SRGB_ALPHA_S3TC_DXT3_EXT;if(i===Nl)return s.COMPRESSED_SRGB_ALPHA_S3TC_DXT5_EXT}else return null;else if(s=e.get("WEBGL_compressed_texture_s3tc"),s!==null){if(i===Rl)return s.COMPRESSED_RGB_S3TC_DXT1_EXT;if(i===Il)return s.COMPRESSED_RGBA_S3TC_DXT1_EXT;if(i===Cl)return s.COMPRESSED_RGBA_S3TC_DXT3_EXT;if(i===Nl)return s.COMPRESSED_RGBA_S3TC_DXT5_EXT}else return null;if(i===gh||i===_h||i===yh||i===xh)if(s=e.get("WEBGL_compressed_texture_pvrtc"),s!==null){if(i===gh)return s.COMPRESSED_RGB_PVRTC_4BPPV1_IMG;if(i===_h)return s.COMPRESSED_RGB_PVRTC_2BPPV1_IMG;if(i===yh)return s.COMPRESSED_RGBA_PVRTC_4BPPV1_IMG;if(i===xh)return s.COMPRESSED_RGBA_PVRTC_2BPPV1_IMG}else return null;if(i===bh||i===vh||i===Sh||i===Eh||i===Mh||i===Pl||i===wh)if(s=e.get("WEBGL_compressed_texture_etc"),s!==null){if(i===bh||i===vh)return o===Lt?s.COMPRESSED_SRGB8_ETC2:s.COMPRESSED_RGB8_ETC2;if(i===Sh)return o===Lt?s.COMPRESSED_SRGB8_ALPHA8_ETC2_EAC:s.COMPRESSED_RGBA8_ETC2_EAC;if(i===Eh)return s.COMPRESSED_R11_EAC;if(i===Mh)return s.COMPRESSED_SIGNED_R11_EAC;if(i===Pl)return s.COMPRESSED_RG11_EAC;if(i===wh)return s.COMPRESSED_SIGNED_RG11_EAC}else return null;if(i===Th||i===Ah||i===Rh||i===Ih||i===Ch||i===Nh||i===Ph||i===Lh||i===Dh||i===Fh||i===Uh||i===Oh||i===Bh||i===kh)if(s=e.get("WEBGL_compressed_texture_astc"),s!==null){if(i===Th)return o===Lt?s.COMPRESSED_SRGB8_ALPHA8_ASTC_4x4_KHR:s.COMPRESSED_RGBA_ASTC_4x4_KHR;if(i===Ah)return o===Lt?s.COMPRESSED_SRGB8_ALPHA8_ASTC_5x4_KHR:s.COMPRESSED_RGBA_ASTC_5x4_KHR;if(i===Rh)return o===Lt?s.COMPRESSED_SRGB8_ALPHA8_ASTC_5x5_KHR:s.COMPRESSED_RGBA_ASTC_5x5_KHR;if(i===Ih)return o===Lt?s.COMPRESSED_SRGB8_ALPHA8_ASTC_6x5_KHR:s.COMPRESSED_RGBA_ASTC_6x5_KHR;if(i===Ch)return o===Lt?s.COMPRESSED_SRGB8_ALPHA8_ASTC_6x6_KHR:s.COMPRESSED_RGBA_ASTC_6x6_KHR;if(i===Nh)return o===Lt?s.COMPRESSED_SRGB8_ALPHA8_ASTC_8x5_KHR:s.COMPRESSED_RGBA_ASTC_8x5_KHR;if(i===Ph)return o===Lt?s.COMPRESSED_SRGB8_ALPHA8_ASTC_8x6_KHR:s.COMPRESSED_RGBA_ASTC_8x6_KHR;if(i===Lh)return o===Lt?s.COMPRESSED_SRGB8_ALPHA8_ASTC_8x8_KHR:s.COMPRESSED_RGBA_ASTC_8x8_KHR;if(i===Dh)return o===Lt?s.COMPRESSED_SRGB8_ALPHA8_ASTC_10x5_KHR:s.COMPRESSED_RGBA_ASTC_10x5_KHR;if(i===Fh)return o===Lt?s.COMPRESSED_SRGB8_ALPHA8_ASTC_10x6_KHR:s.COMPRESSED_RGBA_ASTC_10x6_KHR;if(i===Uh)return o===Lt?s.COMPRESSED_SRGB8_ALPHA8_ASTC_10x8_KHR:s.COMPRESSED_RGBA_ASTC_10x8_KHR;if(i===Oh)return o===Lt?s.COMPRESSED_SRGB8_ALPHA8_ASTC_10x10_KHR:s.COMPRESSED_RGBA_ASTC_10x10_KHR;if(i===Bh)return o===Lt?s.COMPRESSED_SRGB8_ALPHA8_ASTC_12x10_KHR:s.COMPRESSED_RGBA_ASTC_12x10_KHR;if(i===kh)return o===Lt?s.COMPRESSED_SRGB8_ALPHA8_ASTC_12x12_KHR:s.COMPRESSED_RGBA_ASTC_12x12_KHR}else return null;if(i===Vh||i===Gh||i===zh)if(s=e.get("EXT_texture_compression_bptc"),s!==null){if(i===Vh)return o===Lt?s.COMPRESSED_SRGB_ALPHA_BPTC_UNORM_EXT:s.COMPRESSED_RGBA_BPTC_UNORM_EXT;if(i===Gh)return s.COMPRESSED_RGB_BPTC_SIGNED_FLOAT_EXT;if(i===zh)return s.COMPRESSED_RGB_BPTC_UNSIGNED_FLOAT_EXT}else return null;if(i===Hh||i===Wh||i===Ll||i===Xh)if(s=e.get("EXT_texture_compression_rgtc"),s!==null){if(i===Hh)return s.COMPRESSED_RED_RGTC1_EXT;if(i===Wh)return s.COMPRESSED_SIGNED_RED_RGTC1_EXT;if(i===Ll)return s.COMPRESSED_RED_GREEN_RGTC2_EXT;if(i===Xh)return s.COMPRESSED_SIGNED_RED_GREEN_RGTC2_EXT}else return null;return i===Ws?n.UNSIGNED_INT_24_8:n[i]!==void 0?n[i]:null}return{convert:t}}var PN=`
void main() {

	gl_Position = vec4( position, 1.0 );

}`,LN=`
uniform sampler2DArray depthColor;
uniform float depthWidth;
uniform float depthHeight;

void main() {

	vec2 coord = vec2( gl_FragCoord.x / depthWidth, gl_FragCoord.y / depthHeight );

	if ( coord.x >= 1.0 ) {

		gl_FragDepth = texture( depthColor, vec3( coord.x - 1.0, coord.y, 1 ) ).r;

	} else {

		gl_FragDepth = texture( depthColor, vec3( coord.x, coord.y, 0 ) ).r;

	}

}`,wm=class{constructor(){this.texture=null,this.mesh=null,this.depthNear=0,this.depthFar=0}init(e,t){if(this.texture===null){let i=new dl(e.texture);(e.depthNear!==t.depthNear||e.depthFar!==t.depthFar)&&(this.depthNear=e.depthNear,this.depthFar=e.depthFar),this.texture=i}}getMesh(e){if(this.texture!==null&&this.mesh===null){let t=e.cameras[0].viewport,i=new _r({vertexShader:PN,fragmentShader:LN,uniforms:{depthColor:{value:this.texture},depthWidth:{value:t.z},depthHeight:{value:t.w}}});this.mesh=new Fi(new gl(20,20),i)}return this.mesh}reset(){this.texture=null,this.mesh=null}getDepthTexture(){return this.texture}},Tm=class extends qi{constructor(e,t){super();let i=this,r=null,s=1,o=null,a="local-floor",l=1,c=null,u=null,h=null,f=null,d=null,p=null,x=typeof XRWebGLBinding<"u",m=new wm,g={},b=t.getContextAttributes(),T=null,v=null,R=[],A=[],_=new Ke,E=null,F=null,N=new ii;N.viewport=new tn;let P=new ii;P.viewport=new tn;let k=[N,P],H=new rh,D=null,W=null;this.cameraAutoUpdate=!0,this.enabled=!1,this.isPresenting=!1,this.getController=function(ee){let me=R[ee];return me===void 0&&(me=new Ko,R[ee]=me),me.getTargetRaySpace()},this.getControllerGrip=function(ee){let me=R[ee];return me===void 0&&(me=new Ko,R[ee]=me),me.getGripSpace()},this.getHand=function(ee){let me=R[ee];return me===void 0&&(me=new Ko,R[ee]=me),me.getHandSpace()};function K(ee){let me=A.indexOf(ee.inputSource);if(me===-1)return;let ye=R[me];ye!==void 0&&(ye.update(ee.inputSource,ee.frame,c||o),ye.dispatchEvent({type:ee.type,data:ee.inputSource}))}function z(){r.removeEventListener("select",K),r.removeEventListener("selectstart",K),r.removeEventListener("selectend",K),r.removeEventListener("squeeze",K),r.removeEventListener("squeezestart",K),r.removeEventListener("squeezeend",K),r.removeEventListener("end",z),r.removeEventListener("inputsourceschange",ce);for(let ee=0;ee<R.length;ee++){let me=A[ee];me!==null&&(A[ee]=null,R[ee].disconnect(me))}D=null,W=null,m.reset();for(let ee in g)delete g[ee];if(e.setRenderTarget(T),d=null,f=null,h=null,r=null,v=null,he.stop(),i.isPresenting=!1,e.setPixelRatio(E),e.setSize(_.width,_.height,!1),F!==null){let ee=F.camera;ee.fov=F.fov,ee.zoom=F.zoom,ee.updateProjectionMatrix(),F=null}i.dispatchEvent({type:"sessionend"})}this.setFramebufferScaleFactor=function(ee){s=ee,i.isPresenting===!0&&$e("WebXRManager: Cannot change framebuffer scale while presenting.")},this.setReferenceSpaceType=function(ee){a=ee,i.isPresenting===!0&&$e("WebXRManager: Cannot change reference space type while presenting.")},this.getReferenceSpace=function(){return c||o},this.setReferenceSpace=function(ee){c=ee},this.getBaseLayer=function(){return f!==null?f:d},this.getBinding=function(){return h===null&&x&&(h=new XRWebGLBinding(r,t)),h},this.getFrame=function(){return p},this.getSession=function(){return r},this.setSession=async function(ee){if(r=ee,r!==null){if(T=e.getRenderTarget(),r.addEventListener("select",K),r.addEventListener("selectstart",K),r.addEventListener("selectend",K),r.addEventListener("squeeze",K),r.addEventListener("squeezestart",K),r.addEventListener("squeezeend",K),r.addEventListener("end",z),r.addEventListener("inputsourceschange",ce),b.xrCompatible!==!0&&await t.makeXRCompatible(),E=e.getPixelRatio(),e.getSize(_),x&&"createProjectionLayer"in XRWebGLBinding.prototype){let ye=null,Ae=null,Se=null;b.depth&&(Se=b.stencil?t.DEPTH24_STENCIL8:t.DEPTH_COMPONENT24,ye=b.stencil?Wr:kr,Ae=b.stencil?Ws:ji);let Xe={colorFormat:t.RGBA8,depthFormat:Se,scaleFactor:s};h=this.getBinding(),f=h.createProjectionLayer(Xe),r.updateRenderState({layers:[f]}),e.setPixelRatio(1),e.setSize(f.textureWidth,f.textureHeight,!1),v=new wi(f.textureWidth,f.textureHeight,{format:er,type:li,depthTexture:new zr(f.textureWidth,f.textureHeight,Ae,void 0,void 0,void 0,void 0,void 0,void 0,ye),stencilBuffer:b.stencil,colorSpace:e.outputColorSpace,samples:b.antialias?4:0,resolveDepthBuffer:f.ignoreDepthValues===!1,resolveStencilBuffer:f.ignoreDepthValues===!1,storeMultisampledDepthBuffer:f.ignoreDepthValues===!1,storeMultisampledStencilBuffer:f.ignoreDepthValues===!1})}else{let ye={antialias:b.antialias,alpha:!0,depth:b.depth,stencil:b.stencil,framebufferScaleFactor:s};d=new XRWebGLLayer(r,t,ye),r.updateRenderState({baseLayer:d}),e.setPixelRatio(1),e.setSize(d.framebufferWidth,d.framebufferHeight,!1),v=new wi(d.framebufferWidth,d.framebufferHeight,{format:er,type:li,colorSpace:e.outputColorSpace,stencilBuffer:b.stencil,resolveDepthBuffer:d.ignoreDepthValues===!1,resolveStencilBuffer:d.ignoreDepthValues===!1,storeMultisampledDepthBuffer:d.ignoreDepthValues===!1,storeMultisampledStencilBuffer:d.ignoreDepthValues===!1})}v.isXRRenderTarget=!0,this.setFoveation(l),c=null,o=await r.requestReferenceSpace(a),he.setContext(r),he.start(),i.isPresenting=!0,i.dispatchEvent({type:"sessionstart"})}},this.getEnvironmentBlendMode=function(){if(r!==null)return r.environmentBlendMode},this.getDepthTexture=function(){return m.getDepthTexture()};function ce(ee){for(let me=0;me<ee.removed.length;me++){let ye=ee.removed[me],Ae=A.indexOf(ye);Ae>=0&&(A[Ae]=null,R[Ae].disconnect(ye))}for(let me=0;me<ee.added.length;me++){let ye=ee.added[me],Ae=A.indexOf(ye);if(Ae===-1){for(let Xe=0;Xe<R.length;Xe++)if(Xe>=A.length){A.push(ye),Ae=Xe;break}else if(A[Xe]===null){A[Xe]=ye,Ae=Xe;break}if(Ae===-1)break}let Se=R[Ae];Se&&Se.connect(ye)}}function J(ee,me){me===null?ee.matrixWorld.copy(ee.matrix):ee.matrixWorld.multiplyMatrices(me.matrixWorld,ee.matrix),ee.matrixWorldInverse.copy(ee.matrixWorld).invert()}this.updateCamera=function(ee){if(r===null)return;let me=ee.near,ye=ee.far;m.texture!==null&&(m.depthNear>0&&(me=m.depthNear),m.depthFar>0&&(ye=m.depthFar)),H.near=P.near=N.near=me,H.far=P.far=N.far=ye,(D!==H.near||W!==H.far)&&(r.updateRenderState({depthNear:H.near,depthFar:H.far}),D=H.near,W=H.far),H.layers.mask=ee.layers.mask|6,N.layers.mask=H.layers.mask&-5,P.layers.mask=H.layers.mask&-3;let Ae=ee.parent,Se=H.cameras;J(H,Ae);for(let Xe=0;Xe<Se.length;Xe++)J(Se[Xe],Ae);H.projectionMatrix.copy(N.projectionMatrix),H.projectionMatrixInverse.copy(N.projectionMatrixInverse),F===null&&ee.isPerspectiveCamera&&(F={camera:ee,fov:ee.fov,zoom:ee.zoom}),Q(ee,H,Ae)};function Q(ee,me,ye){ye===null?ee.matrix.copy(me.matrixWorld):(ee.matrix.copy(ye.matrixWorld),ee.matrix.invert(),ee.matrix.multiply(me.matrixWorld)),ee.matrix.decompose(ee.position,ee.quaternion,ee.scale),ee.updateMatrixWorld(!0),ee.projectionMatrix.copy(me.projectionMatrix),ee.projectionMatrixInverse.copy(me.projectionMatrixInverse),ee.isPerspectiveCamera&&(ee.fov=Xo*2*Math.atan(1/ee.projectionMatrix.elements[5]),ee.zoom=1)}this.getCamera=function(){return H},this.getFoveation=function(){if(!(f===null&&d===null))return l},this.setFoveation=function(ee){l=ee,f!==null&&(f.fixedFoveation=ee),d!==null&&d.fixedFoveation!==void 0&&(d.fixedFoveation=ee)},this.hasDepthSensing=function(){return m.texture!==null},this.getDepthSensingMesh=function(){return m.getMesh(H)},this.getCameraTexture=function(ee){return g[ee]};let re=null;function fe(ee,me){if(u=me.getViewerPose(c||o),p=me,u!==null){let ye=u.views;d!==null&&(e.setRenderTargetFramebuffer(v,d.framebuffer),e.setRenderTarget(v));let Ae=!1;ye.length!==H.cameras.length&&(H.cameras.length=0,Ae=!0);for(let ze=0;ze<ye.length;ze++){let ft=ye[ze],ct=null;if(d!==null)ct=d.getViewport(ft);else{let Qt=h.getViewSubImage(f,ft);ct=Qt.viewport,ze===0&&(e.setRenderTargetTextures(v,Qt.colorTexture,Qt.depthStencilTexture),e.setRenderTarget(v))}let rt=k[ze];rt===void 0&&(rt=new ii,rt.layers.enable(ze),rt.viewport=new tn,k[ze]=rt),rt.matrix.fromArray(ft.transform.matrix),rt.matrix.decompose(rt.position,rt.quaternion,rt.scale),rt.projectionMatrix.fromArray(ft.projectionMatrix),rt.projectionMatrixInverse.copy(rt.projectionMatrix).invert(),rt.viewport.set(ct.x,ct.y,ct.width,ct.height),ze===0&&(H.matrix.copy(rt.matrix),H.matrix.decompose(H.position,H.quaternion,H.scale)),Ae===!0&&H.cameras.push(rt)}let Se=r.enabledFeatures;if(Se&&Se.includes("depth-sensing")&&r.depthUsage=="gpu-optimized"&&x){h=i.getBinding();let ze=h.getDepthInformation(ye[0]);ze&&ze.isValid&&ze.texture&&m.init(ze,r.renderState)}if(Se&&Se.includes("camera-access")&&x){e.state.unbindTexture(),h=i.getBinding();for(let ze=0;ze<ye.length;ze++){let ft=ye[ze].camera;if(ft){let ct=g[ft];ct||(ct=new dl,g[ft]=ct);let rt=h.getCameraImage(ft);ct.sourceTexture=rt}}}}for(let ye=0;ye<R.length;ye++){let Ae=A[ye],Se=R[ye];Ae!==null&&Se!==void 0&&Se.update(Ae,me,c||o)}re&&re(ee,me),me.detectedPlanes&&i.dispatchEvent({type:"planesdetected",data:me}),p=null}let he=new vv;he.setAnimationLoop(fe),this.setAnimationLoop=function(ee){re=ee},this.dispose=function(){}}},DN=new Tt,Nv=new it;Nv.set(-1,0,0,0,1,0,0,0,1);function FN(n,e){function t(m,g){m.matrixAutoUpdate===!0&&m.updateMatrix(),g.value.copy(m.matrix)}function i(m,g){g.color.getRGB(m.fogColor.value,dm(n)),g.isFog?(m.fogNear.value=g.near,m.fogFar.value=g.far):g.isFogExp2&&(m.fogDensity.value=g.density)}function r(m,g,b,T,v){g.isNodeMaterial?g.uniformsNeedUpdate=!1:g.isMeshBasicMaterial?s(m,g):g.isMeshLambertMaterial?(s(m,g),g.envMap&&(m.envMapIntensity.value=g.envMapIntensity)):g.isMeshToonMaterial?(s(m,g),h(m,g)):g.isMeshPhongMaterial?(s(m,g),u(m,g),g.envMap&&(m.envMapIntensity.value=g.envMapIntensity)):g.isMeshStandardMaterial?(s(m,g),f(m,g),g.isMeshPhysicalMaterial&&d(m,g,v)):g.isMeshMatcapMaterial?(s(m,g),p(m,g)):g.isMeshDepthMaterial?s(m,g):g.isMeshDistanceMaterial?(s(m,g),x(m,g)):g.isMeshNormalMaterial?s(m,g):g.isLineBasicMaterial?(o(m,g),g.isLineDashedMaterial&&a(m,g)):g.isPointsMaterial?l(m,g,b,T):g.isSpriteMaterial?c(m,g):g.isShadowMaterial?(m.color.value.copy(g.color),m.opacity.value=g.opacity):g.isShaderMaterial&&(g.uniformsNeedUpdate=!1)}function s(m,g){m.opacity.value=g.opacity,g.color&&m.diffuse.value.copy(g.color),g.emissive&&m.emissive.value.copy(g.emissive).multiplyScalar(g.emissiveIntensity),g.map&&(m.map.value=g.map,t(g.map,m.mapTransform)),g.alphaMap&&(m.alphaMap.value=g.alphaMap,t(g.alphaMap,m.alphaMapTransform)),g.bumpMap&&(m.bumpMap.value=g.bumpMap,t(g.bumpMap,m.bumpMapTransform),m.bumpScale.value=g.bumpScale,g.side===si&&(m.bumpScale.value*=-1)),g.normalMap&&(m.normalMap.value=g.normalMap,t(g.normalMap,m.normalMapTransform),m.normalScale.value.copy(g.normalScale),g.side===si&&m.normalScale.value.negate()),g.displacementMap&&(m.displacementMap.value=g.displacementMap,t(g.displacementMap,m.displacementMapTransform),m.displacementScale.value=g.displacementScale,m.displacementBias.value=g.displacementBias),g.emissiveMap&&(m.emissiveMap.value=g.emissiveMap,t(g.emissiveMap,m.emissiveMapTransform)),g.specularMap&&(m.specularMap.value=g.specularMap,t(g.specularMap,m.specularMapTransform)),g.alphaTest>0&&(m.alphaTest.value=g.alphaTest);let b=e.get(g),T=b.envMap,v=b.envMapRotation;T&&(m.envMap.value=T,m.envMapRotation.value.setFromMatrix4(DN.makeRotationFromEuler(v)).transpose(),T.isCubeTexture&&T.isRenderTargetTexture===!1&&m.envMapRotation.value.premultiply(Nv),m.reflectivity.value=g.reflectivity,m.ior.value=g.ior,m.refractionRatio.value=g.refractionRatio),g.lightMap&&(m.lightMap.value=g.lightMap,m.lightMapIntensity.value=g.lightMapIntensity,t(g.lightMap,m.lightMapTransform)),g.aoMap&&(m.aoMap.value=g.aoMap,m.aoMapIntensity.value=g.aoMapIntensity,t(g.aoMap,m.aoMapTransform))}function o(m,g){m.diffuse.value.copy(g.color),m.opacity.value=g.opacity,g.map&&(m.map.value=g.map,t(g.map,m.mapTransform))}function a(m,g){m.dashSize.value=g.dashSize,m.totalSize.value=g.dashSize+g.gapSize,m.scale.value=g.scale}function l(m,g,b,T){m.diffuse.value.copy(g.color),m.opacity.value=g.opacity,m.size.value=g.size*b,m.scale.value=T*.5,g.map&&(m.map.value=g.map,t(g.map,m.uvTransform)),g.alphaMap&&(m.alphaMap.value=g.alphaMap,t(g.alphaMap,m.alphaMapTransform)),g.alphaTest>0&&(m.alphaTest.value=g.alphaTest)}function c(m,g){m.diffuse.value.copy(g.color),m.opacity.value=g.opacity,m.rotation.value=g.rotation,g.map&&(m.map.value=g.map,t(g.map,m.mapTransform)),g.alphaMap&&(m.alphaMap.value=g.alphaMap,t(g.alphaMap,m.alphaMapTransform)),g.alphaTest>0&&(m.alphaTest.value=g.alphaTest)}function u(m,g){m.specular.value.copy(g.specular),m.shininess.value=Math.max(g.shininess,1e-4)}function h(m,g){g.gradientMap&&(m.gradientMap.value=g.gradientMap)}function f(m,g){m.metalness.value=g.metalness,g.metalnessMap&&(m.metalnessMap.value=g.metalnessMap,t(g.metalnessMap,m.metalnessMapTransform)),m.roughness.value=g.roughness,g.roughnessMap&&(m.roughnessMap.value=g.roughnessMap,t(g.roughnessMap,m.roughnessMapTransform)),g.envMap&&(m.envMapIntensity.value=g.envMapIntensity)}function d(m,g,b){m.ior.value=g.ior,g.diffuseRoughness>0&&(m.diffuseRoughness.value=g.diffuseRoughness,g.diffuseRoughnessMap&&(m.diffuseRoughnessMap.value=g.diffuseRoughnessMap,t(g.diffuseRoughnessMap,m.diffuseRoughnessMapTransform))),g.sheen>0&&(m.sheenColor.value.copy(g.sheenColor).multiplyScalar(g.sheen),m.sheenRoughness.value=g.sheenRoughness,g.sheenColorMap&&(m.sheenColorMap.value=g.sheenColorMap,t(g.sheenColorMap,m.sheenColorMapTransform)),g.sheenRoughnessMap&&(m.sheenRoughnessMap.value=g.sheenRoughnessMap,t(g.sheenRoughnessMap,m.sheenRoughnessMapTransform))),g.clearcoat>0&&(m.clearcoat.value=g.clearcoat,m.clearcoatRoughness.value=g.clearcoatRoughness,g.clearcoatMap&&(m.clearcoatMap.value=g.clearcoatMap,t(g.clearcoatMap,m.clearcoatMapTransform)),g.clearcoatRoughnessMap&&(m.clearcoatRoughnessMap.value=g.clearcoatRoughnessMap,t(g.clearcoatRoughnessMap,m.clearcoatRoughnessMapTransform)),g.clearcoatNormalMap&&(m.clearcoatNormalMap.value=g.clearcoatNormalMap,t(g.clearcoatNormalMap,m.clearcoatNormalMapTransform),m.clearcoatNormalScale.value.copy(g.clearcoatNormalScale),g.side===si&&m.clearcoatNormalScale.value.negate())),g.dispersion>0&&(m.dispersion.value=g.dispersion),g.retroreflectivity>0&&(m.retroreflectivity.value=g.retroreflectivity),g.iridescence>0&&(m.iridescence.value=g.iridescence,m.iridescenceIOR.value=g.iridescenceIOR,m.iridescenceThicknessMinimum.value=g.iridescenceThicknessMinimum,m.iridescenceThicknessMaximum.value=g.iridescenceThicknessMaximum,g.iridescenceMap&&(m.iridescenceMap.value=g.iridescenceMap,t(g.iridescenceMap,m.iridescenceMapTransform)),g.iridescenceThicknessMap&&(m.iridescenceThicknessMap.value=g.iridescenceThicknessMap,t(g.iridescenceThicknessMap,m.iridescenceThicknessMapTransform))),g.transmission>0&&(m.transmission.value=g.transmission,m.transmissionSamplerMap.value=b.texture,m.transmissionSamplerSize.value.set(b.width,b.height),g.transmissionMap&&(m.transmissionMap.value=g.transmissionMap,t(g.transmissionMap,m.transmissionMapTransform)),m.thickness.value=g.thickness,g.thicknessMap&&(m.thicknessMap.value=g.thicknessMap,t(g.thicknessMap,m.thicknessMapTransform)),m.attenuationDistance.value=g.attenuationDistance,m.attenuationColor.value.copy(g.attenuationColor)),g.anisotropy>0&&(m.anisotropyVector.value.set(g.anisotropy*Math.cos(g.anisotropyRotation),g.anisotropy*Math.sin(g.anisotropyRotation)),g.anisotropyMap&&(m.anisotropyMap.value=g.anisotropyMap,t(g.anisotropyMap,m.anisotropyMapTransform))),m.specularIntensity.value=g.specularIntensity,m.specularColor.value.copy(g.specularColor),g.specularColorMap&&(m.specularColorMap.value=g.specularColorMap,t(g.specularColorMap,m.specularColorMapTransform)),g.specularIntensityMap&&(m.specularIntensityMap.value=g.specularIntensityMap,t(g.specularIntensityMap,m.specularIntensityMapTransform))}function p(m,g){g.matcap&&(m.matcap.value=g.matcap)}function x(m,g){let b=e.get(g).light;m.referencePosition.value.setFromMatrixPosition(b.matrixWorld),m.nearDistance.value=b.shadow.camera.near,m.farDistance.value=b.shadow.camera.far}return{refreshFogUniforms:i,refreshMaterialUniforms:r}}function UN(n,e,t,i){let r={},s={};function o(b,T){let v=T.program;i.uniformBlockBinding(b,v,r[b.id])}function a(b,T){let v=r[b.id];v===void 0&&(p(b),v=l(b),r[b.id]=v,b.addEventListener("dispose",m));let R=T.program;i.updateUBOMapping(b,R);let A=e.render.frame;s[b.id]!==A&&(c(b),s[b.id]=A)}function l(b){let T=n.createBuffer(),v=b.__size,R=b.usage;return n.bindBuffer(n.UNIFORM_BUFFER,T),n.bufferData(n.UNIFORM_BUFFER,v,R),n.bindBuffer(n.UNIFORM_BUFFER,null),T}function c(b){let T=r[b.id],v=b.uniforms,R=b.__cache;n.bindBuffer(n.UNIFORM_BUFFER,T);for(let A=0,_=v.length;A<_;A++){let E=v[A];if(Array.isArray(E))for(let F=0,N=E.length;F<N;F++)u(E[F],A,F,R);else u(E,A,0,R)}n.bindBuffer(n.UNIFORM_BUFFER,null)}function u(b,T,v,R){if(f(b,T,v,R)===!0){let A=b.__offset,_=b.value;if(Array.isArray(_)){let E=0;for(let F=0;F<_.length;F++){let N=_[F],P=x(N,!0);h(N,b.__data,E),E+=P.storage/Float32Array.BYTES_PER_ELEMENT}}else h(_,b.__data,0);n.bufferSubData(n.UNIFORM_BUFFER,A,b.__data)}}function h(b,T,v){typeof b=="number"||typeof b=="boolean"?T[v]=b:b.isMatrix3?(T[v]=b.elements[0],T[v+1]=b.elements[1],T[v+2]=b.elements[2],T[v+3]=0,T[v+4]=b.elements[3],T[v+5]=b.elements[4],T[v+6]=b.elements[5],T[v+7]=0,T[v+8]=b.elements[6],T[v+9]=b.elements[7],T[v+10]=b.elements[8],T[v+11]=0):ArrayBuffer.isView(b)?T.set(b.subarray(0,T.length-v),v):b.toArray(T,v)}function f(b,T,v,R){let A=b.value,_=T+"_"+v;if(Array.isArray(A)){R[_]===void 0&&(R[_]=[]);let E=R[_],F=!1;for(let N=0;N<A.length;N++)d(A[N],E,N)===!0&&(F=!0);return F}return d(A,R,_)}function d(b,T,v){if(T[v]===void 0)return typeof b=="number"||typeof b=="boolean"?T[v]=b:ArrayBuffer.isView(b)?T[v]=b.slice():T[v]=b.clone(),!0;{let R=T[v];if(typeof b=="number"||typeof b=="boolean"){if(R!==b)return T[v]=b,!0}else{if(ArrayBuffer.isView(b))return!0;if(R.equals(b)===!1)return R.copy(b),!0}}return!1}function p(b){let T=b.uniforms,v=0,R=16;for(let _=0,E=T.length;_<E;_++){let F=Array.isArray(T[_])?T[_]:[T[_]];for(let N=0,P=F.length;N<P;N++){let k=F[N],H=Array.isArray(k.value)?k.value:[k.value],D=Array.isArray(T[_])||Array.isArray(k.value),W=v;for(let z=0,ce=H.length;z<ce;z++){let J=H[z],Q=x(J,D),re=v%R,fe=re%Q.boundary,he=re+fe;v+=fe,he!==0&&R-he<Q.storage&&(v+=R-he),z===0&&(W=v),v+=Q.storage}let K=k.type==="int"?Int32Array:k.type==="uint"?Uint32Array:Float32Array;k.__data=new K((v-W)/Float32Array.BYTES_PER_ELEMENT),k.__offset=W}}let A=v%R;return A>0&&(v+=R-A),b.__size=v,b.__cache={},this}function x(b,T){let v={boundary:0,storage:0};return typeof b=="number"||typeof b=="boolean"?(v.boundary=4,v.storage=4):b.isVector2?(v.boundary=8,v.storage=8):b.isVector3||b.isColor?(v.boundary=16,v.storage=12):b.isVector4?(v.boundary=16,v.storage=16):b.isMatrix3?(v.boundary=16,v.storage=48):b.isMatrix4?(v.boundary=16,v.storage=64):b.isTexture?$e("WebGLRenderer: Texture samplers can not be part of an uniforms group."):ArrayBuffer.isView(b)?(v.boundary=16,v.storage=b.byteLength):$e("WebGLRenderer: Unsupported uniform value type.",b),T===!0&&(v.boundary=16,v.storage=Math.ceil(v.storage/16)*16),v}function m(b){let T=b.target;T.removeEventListener("dispose",m),n.deleteBuffer(r[T.id]),delete r[T.id],delete s[T.id]}function g(){for(let b in r)n.deleteBuffer(r[b]);r={},s={}}return{bind:o,update:a,dispose:g}}var ON=new Uint16Array([12469,15057,12620,14925,13266,14620,13807,14376,14323,13990,14545,13625,14713,13328,14840,12882,14931,12528,14996,12233,15039,11829,15066,11525,15080,11295,15085,10976,15082,10705,15073,10495,13880,14564,13898,14542,13977,14430,14158,14124,14393,13732,14556,13410,14702,12996,14814,12596,14891,12291,14937,11834,14957,11489,14958,11194,14943,10803,14921,10506,14893,10278,14858,9960,14484,14039,14487,14025,14499,13941,14524,13740,14574,13468,14654,13106,14743,12678,14818,12344,14867,11893,14889,11509,14893,11180,14881,10751,14852,10428,14812,10128,14765,9754,14712,9466,14764,13480,14764,13475,14766,13440,14766,13347,14769,13070,14786,12713,14816,12387,14844,11957,14860,11549,14868,11215,14855,10751,14825,10403,14782,10044,14729,9651,14666,9352,14599,9029,14967,12835,14966,12831,14963,12804,14954,12723,14936,12564,14917,12347,14900,11958,14886,11569,14878,11247,14859,10765,14828,10401,14784,10011,14727,9600,14660,9289,14586,8893,14508,8533,15111,12234,15110,12234,15104,12216,15092,12156,15067,12010,15028,11776,14981,11500,14942,11205,14902,10752,14861,10393,14812,9991,14752,9570,14682,9252,14603,8808,14519,8445,14431,8145,15209,11449,15208,11451,15202,11451,15190,11438,15163,11384,15117,11274,15055,10979,14994,10648,14932,10343,14871,9936,14803,9532,14729,9218,14645,8742,14556,8381,14461,8020,14365,7603,15273,10603,15272,10607,15267,10619,15256,10631,15231,10614,15182,10535,15118,10389,15042,10167,14963,9787,14883,9447,14800,9115,14710,8665,14615,8318,14514,7911,14411,7507,14279,7198,15314,9675,15313,9683,15309,9712,15298,9759,15277,9797,15229,9773,15166,9668,15084,9487,14995,9274,14898,8910,14800,8539,14697,8234,14590,7790,14479,7409,14367,7067,14178,6621,15337,8619,15337,8631,15333,8677,15325,8769,15305,8871,15264,8940,15202,8909,15119,8775,15022,8565,14916,8328,14804,8009,14688,7614,14569,7287,14448,6888,14321,6483,14088,6171,15350,7402,15350,7419,15347,7480,15340,7613,15322,7804,15287,7973,15229,8057,15148,8012,15046,7846,14933,7611,14810,7357,14682,7069,14552,6656,14421,6316,14251,5948,14007,5528,15356,5942,15356,5977,15353,6119,15348,6294,15332,6551,15302,6824,15249,7044,15171,7122,15070,7050,14949,6861,14818,6611,14679,6349,14538,6067,14398,5651,14189,5311,13935,4958,15359,4123,15359,4153,15356,4296,15353,4646,15338,5160,15311,5508,15263,5829,15188,6042,15088,6094,14966,6001,14826,5796,14678,5543,14527,5287,14377,4985,14133,4586,13869,4257,15360,1563,15360,1642,15358,2076,15354,2636,15341,3350,15317,4019,15273,4429,15203,4732,15105,4911,14981,4932,14836,4818,14679,4621,14517,4386,14359,4156,14083,3795,13808,3437,15360,122,15360,137,15358,285,15355,636,15344,1274,15322,2177,15281,2765,15215,3223,15120,3451,14995,3569,14846,3567,14681,3466,14511,3305,14344,3121,14037,2800,13753,2467,15360,0,15360,1,15359,21,15355,89,15346,253,15325,479,15287,796,15225,1148,15133,1492,15008,1749,14856,1882,14685,1886,14506,1783,14324,1608,13996,1398,13702,1183]),br=null;function BN(){return br===null&&(br=new cl(ON,16,16,bs,Qi),br.name="DFG_LUT",br.minFilter=ri,br.magFilter=ri,br.wrapS=mr,br.wrapT=mr,br.generateMipmaps=!1,br.needsUpdate=!0),br}var qh=class{constructor(e={}){let{canvas:t=Wb(),context:i=null,depth:r=!0,stencil:s=!1,alpha:o=!1,antialias:a=!1,premultipliedAlpha:l=!0,preserveDrawingBuffer:c=!1,powerPreference:u="default",failIfMajorPerformanceCaveat:h=!1,reversedDepthBuffer:f=!1,outputBufferType:d=li}=e;this.isWebGLRenderer=!0;let p;if(i!==null){if(typeof WebGLRenderingContext<"u"&&i instanceof WebGLRenderingContext)throw new Error("THREE.WebGLRenderer: WebGL 1 is not supported since r163.");p=i.getContextAttributes().alpha}else p=o;let x=d,m=new Set([mh,ph,dh]),g=new Set([li,ji,na,Ws,uh,hh]),b=new Uint32Array(4),T=new Int32Array(4),v={textures:[],min:[],max:[],resolution:[]},R=null,A=null,_=[],E=[],F=null;this.domElement=t,this.debug={checkShaderErrors:!0,diagnostics:{keywords:!1},onShaderError:null},this.autoClear=!0,this.autoClearColor=!0,this.autoClearDepth=!0,this.autoClearStencil=!0,this.sortObjects=!0,this.clippingPlanes=[],this.localClippingEnabled=!1,this.toneMapping=xr,this.toneMappingExposure=1,this.transmissionResolutionScale=1;let N=this,P=!1,k=null,H=null,D=null,W=null;this._outputColorSpace=Si;let K=0,z=0,ce=null,J=-1,Q=null,re=new tn,fe=new tn,he=null,ee=new tt(0),me=0,ye=t.width,Ae=t.height,Se=1,Xe=null,ot=null,ze=new tn(0,0,ye,Ae),ft=new tn(0,0,ye,Ae),ct=!1,rt=new fs,Qt=new Bu,Xt=!1,mn=!1,Ot=new Tt,Ln=new X,wt=new tn,Mn={background:null,fog:null,environment:null,overrideMaterial:null,isScene:!0},sn=!1;function gn(){return ce===null?Se:1}let O=i;function Ie(w,B){return t.getContext(w,B)}let qe,at,Ee,Vt,Ge,Ze,I,S,Y,ue,oe,_e,xe,te,ie,pe,U,se,ne,Me,ge,ve,He;try{let w={alpha:!0,depth:r,stencil:s,antialias:a,premultipliedAlpha:l,preserveDrawingBuffer:c,powerPreference:u,failIfMajorPerformanceCaveat:h};if("setAttribute"in t&&t.setAttribute("data-engine",`three.js r${"187"}`),t.addEventListener("webglcontextlost",Be,!1),t.addEventListener("webglcontextrestored",Qe,!1),t.addEventListener("webglcontextcreationerror",Re,!1),O===null){let B="webgl2";if(O=Ie(B,w),O===null)throw Ie(B)?new Error("THREE.WebGLRenderer: Error creating WebGL context with your selected attributes."):new Error("THREE.WebGLRenderer: Error creating WebGL context.")}je()}catch(w){throw t.removeEventListener("webglcontextlost",Be,!1),t.removeEventListener("webglcontextrestored",Qe,!1),t.removeEventListener("webglcontextcreationerror",Re,!1),et("WebGLRenderer: "+w.message),w}function je(){qe=new $I(O),qe.init(),ge=new NN(O,qe),at=new BI(O,qe,e,ge),Ee=new IN(O,qe),at.reversedDepthBuffer&&f&&Ee.buffers.depth.setReversed(!0),H=O.createFramebuffer(),D=O.createFramebuffer(),W=O.createFramebuffer(),Vt=new jI(O),Ge=new mN,Ze=new CN(O,qe,Ee,Ge,at,ge,Vt),I=new KI(N),S=new e1(O),ve=new UI(O,S),Y=new qI(O,S,Vt,ve),ue=new eC(O,Y,S,ve,Vt),se=new QI(O,at,Ze),ie=new kI(Ge),oe=new pN(N,I,qe,at,ve,ie),_e=new FN(N,Ge),xe=new _N,te=new EN(qe),U=new FI(N,I,Ee,ue,p,l),pe=new RN(N,ue,at),He=new UN(O,Vt,at,Ee),ne=new OI(O,qe,Vt),Me=new JI(O,qe,Vt),Vt.programs=oe.programs,N.capabilities=at,N.extensions=qe,N.properties=Ge,N.renderLists=xe,N.shadowMap=pe,N.state=Ee,N.info=Vt}x!==li&&(F=new nC(x,t.width,t.height,a,r,s));let le=new Tm(N,O);this.xr=le,this.getContext=function(){return O},this.getContextAttributes=function(){return O.getContextAttributes()},this.forceContextLoss=function(){let w=qe.get("WEBGL_lose_context");w&&w.loseContext()},this.forceContextRestore=function(){let w=qe.get("WEBGL_lose_context");w&&w.restoreContext()},this.getPixelRatio=function(){return Se},this.setPixelRatio=function(w){w!==void 0&&(Se=w,this.setSize(ye,Ae,!1))},this.getSize=function(w){return w.set(ye,Ae)},this.setSize=function(w,B,j=!0){if(le.isPresenting){$e("WebGLRenderer: Can't change size while VR device is presenting.");return}ye=w,Ae=B,t.width=Math.floor(w*Se),t.height=Math.floor(B*Se),j===!0&&(t.style.width=w+"px",t.style.height=B+"px"),F!==null&&F.setSize(t.width,t.height),this.setViewport(0,0,w,B)},this.getDrawingBufferSize=function(w){return w.set(ye*Se,Ae*Se).floor()},this.setDrawingBufferSize=function(w,B,j){ye=w,Ae=B,Se=j,t.width=Math.floor(w*j),t.height=Math.floor(B*j),this.setViewport(0,0,w,B)},this.setEffects=function(w){if(x===li){et("WebGLRenderer: setEffects() requires outputBufferType set to HalfFloatType or FloatType.");return}if(w){for(let B=0;B<w.length;B++)if(w[B].isOutputPass===!0){$e("WebGLRenderer: OutputPass is not needed in setEffects(). Tone mapping and color space conversion are applied automatically.");break}}F.setEffects(w||[])},this.getCurrentViewport=function(w){return w.copy(re)},this.getViewport=function(w){return w.copy(ze)},this.setViewport=function(w,B,j,Z){w.isVector4?ze.set(w.x,w.y,w.z,w.w):ze.set(w,B,j,Z),Ee.viewport(re.copy(ze).multiplyScalar(gn()).round())},this.getScissor=function(w){return w.copy(ft)},this.setScissor=function(w,B,j,Z){w.isVector4?ft.set(w.x,w.y,w.z,w.w):ft.set(w,B,j,Z),Ee.scissor(fe.copy(ft).multiplyScalar(gn()).round())},this.getScissorTest=function(){return ct},this.setScissorTest=function(w){Ee.setScissorTest(ct=w)},this.setOpaqueSort=function(w){Xe=w},this.setTransparentSort=function(w){ot=w},this.getClearColor=function(w){return w.copy(U.getClearColor())},this.setClearColor=function(){U.setClearColor(...arguments)},this.getClearAlpha=function(){return U.getClearAlpha()},this.setClearAlpha=function(){U.setClearAlpha(...arguments)},this.clear=function(w=!0,B=!0,j=!0){let Z=0;if(w){let $=!1;if(ce!==null){let we=ce.texture.format;$=m.has(we)}if($){let we=ce.texture.type,Ce=g.has(we),Te=U.getClearColor(),Ne=U.getClearAlpha(),Ve=Te.r,nt=Te.g,mt=Te.b;Ce?(b[0]=Ve,b[1]=nt,b[2]=mt,b[3]=Ne,O.clearBufferuiv(O.COLOR,0,b)):(T[0]=Ve,T[1]=nt,T[2]=mt,T[3]=Ne,O.clearBufferiv(O.COLOR,0,T))}else Z|=O.COLOR_BUFFER_BIT}B&&(Z|=O.DEPTH_BUFFER_BIT,this.state.buffers.depth.setMask(!0)),j&&(Z|=O.STENCIL_BUFFER_BIT,this.state.buffers.stencil.setMask(4294967295)),Z!==0&&O.clear(Z)},this.clearColor=function(){this.clear(!0,!1,!1)},this.clearDepth=function(){this.clear(!1,!0,!1)},this.clearStencil=function(){this.clear(!1,!1,!0)},this.setNodesHandler=function(w){w.setRenderer(this),k=w},this.dispose=function(){t.removeEventListener("webglcontextlost",Be,!1),t.removeEventListener("webglcontextrestored",Qe,!1),t.removeEventListener("webglcontextcreationerror",Re,!1),U.dispose(),xe.dispose(),te.dispose(),Ze.dispose(),Ge.dispose(),I.dispose(),ue.dispose(),Y.dispose(),ve.dispose(),He.dispose(),oe.dispose(),le.dispose(),le.removeEventListener("sessionstart",zl),le.removeEventListener("sessionend",ir),Sr.stop()};function Be(w){w.preventDefault(),cm("WebGLRenderer: Context Lost."),P=!0}function Qe(){cm("WebGLRenderer: Context Restored."),P=!1;let w=Vt.autoReset,B=pe.enabled,j=pe.autoUpdate,Z=pe.needsUpdate,$=pe.type;je(),Vt.autoReset=w,pe.enabled=B,pe.autoUpdate=j,pe.needsUpdate=Z,pe.type=$}function Re(w){et("WebGLRenderer: A WebGL context could not be created. Reason: ",w.statusMessage)}function lt(w){let B=w.target;B.removeEventListener("dispose",lt),Yt(B)}function Yt(w){Jn(w),Ge.remove(w)}function Jn(w){let B=Ge.get(w).programs;B!==void 0&&(B.forEach(function(j){oe.releaseProgram(j)}),w.isShaderMaterial&&oe.releaseShaderCache(w))}this.renderBufferDirect=function(w,B,j,Z,$,we){B===null&&(B=Mn);let Ce=$.isMesh&&$.matrixWorld.determinantAffine()<0,Te=_a(w,B,j,Z,$);Ee.setMaterial(Z,Ce);let Ne=j.index,Ve=1;if(Z.wireframe===!0){if(Ne=Y.getWireframeAttribute(j),Ne===void 0)return;Ve=2}let nt=j.drawRange,mt=j.attributes.position,ke=nt.start*Ve,gt=(nt.start+nt.count)*Ve;we!==null&&(ke=Math.max(ke,we.start*Ve),gt=Math.min(gt,(we.start+we.count)*Ve)),Ne!==null?(ke=Math.max(ke,0),gt=Math.min(gt,Ne.count)):mt!=null&&(ke=Math.max(ke,0),gt=Math.min(gt,mt.count));let rn=gt-ke;if(rn<0||rn===1/0)return;ve.setup($,Z,Te,j,Ne);let Dt,Ft=ne;if(Ne!==null&&(Dt=S.get(Ne),Ft=Me,Ft.setIndex(Dt)),$.isMesh)Z.wireframe===!0?(Ee.setLineWidth(Z.wireframeLinewidth*gn()),Ft.setMode(O.LINES)):Ft.setMode(O.TRIANGLES);else if($.isLine){let wn=Z.linewidth;wn===void 0&&(wn=1),Ee.setLineWidth(wn*gn()),$.isLineSegments?Ft.setMode(O.LINES):$.isLineLoop?Ft.setMode(O.LINE_LOOP):Ft.setMode(O.LINE_STRIP)}else $.isPoints?Ft.setMode(O.POINTS):$.isSprite&&Ft.setMode(O.TRIANGLES);if($.isBatchedMesh)if(qe.get("WEBGL_multi_draw"))Ft.renderMultiDraw($._multiDrawStarts,$._multiDrawCounts,$._multiDrawCount);else{let wn=$._multiDrawStarts,Fe=$._multiDrawCounts,_n=$._multiDrawCount,bt=Ne?S.get(Ne).bytesPerElement:1,Mr=Ge.get(Z).currentProgram.getUniforms();for(let yn=0;yn<_n;yn++)Mr.setValue(O,"_gl_DrawID",yn),Ft.render(wn[yn]/bt,Fe[yn])}else if($.isInstancedMesh)Ft.renderInstances(ke,rn,$.count);else if(j.isInstancedBufferGeometry){let wn=j._maxInstanceCount!==void 0?j._maxInstanceCount:1/0,Fe=Math.min(j.instanceCount,wn);Ft.renderInstances(ke,rn,Fe)}else Ft.render(ke,rn)};function pa(w,B,j,Z){k!==null&&w.isNodeMaterial&&k.setObject(Z,w),Xt===!0&&ie.setState(w,j,!1),w.transparent===!0&&w.side===yr&&w.forceSinglePass===!1?(w.side=si,w.needsUpdate=!0,rr(w,B,Z),w.side=xs,w.needsUpdate=!0,rr(w,B,Z),w.side=yr):rr(w,B,Z)}this.compile=function(w,B,j=null){j===null&&(j=w),k!==null&&k.renderStart(w,B,j),A=te.get(j),A.init(B),E.push(A),j.traverseVisible(function($){$.isLight&&$.layers.test(B.layers)&&(A.pushLight($),$.castShadow&&A.pushShadow($))}),w!==j&&w.traverseVisible(function($){$.isLight&&$.layers.test(B.layers)&&(A.pushLight($),$.castShadow&&A.pushShadow($))}),A.setupLights(),k!==null&&k.updateLights(A.state.lightsArray),mn=this.localClippingEnabled,Xt=ie.init(this.clippingPlanes,mn),Xt===!0&&ie.setGlobalState(this.clippingPlanes,B),k!==null&&pe.render(A.state.shadowsArray,j,B);let Z=new Set;return w.traverse(function($){if(!($.isMesh||$.isPoints||$.isLine||$.isSprite))return;let we=$.material;if(we)if(Array.isArray(we))for(let Ce=0;Ce<we.length;Ce++){let Te=we[Ce];pa(Te,j,B,$),Z.add(Te)}else pa(we,j,B,$),Z.add(we)}),A=E.pop(),k!==null&&k.renderEnd(),Z},this.compileAsync=function(w,B,j=null){let Z=this.compile(w,B,j);return new Promise($=>{function we(){if(Z.forEach(function(Ce){let Ne=Ge.get(Ce).currentProgram;(Ne===void 0||Ne.isReady())&&Z.delete(Ce)}),Z.size===0){$(w);return}setTimeout(we,10)}qe.get("KHR_parallel_shader_compile")!==null?we():setTimeout(we,10)})};let Zs=null;function ff(w){Zs&&Zs(w)}function zl(){Sr.stop()}function ir(){Sr.start()}let Sr=new vv;Sr.setAnimationLoop(ff),typeof self<"u"&&Sr.setContext(self),this.setAnimationLoop=function(w){Zs=w,le.setAnimationLoop(w),w===null?Sr.stop():Sr.start()},le.addEventListener("sessionstart",zl),le.addEventListener("sessionend",ir),this.render=function(w,B){if(B!==void 0&&B.isCamera!==!0){et("WebGLRenderer.render: camera is not an instance of THREE.Camera.");return}if(P===!0)return;k!==null&&k.renderStart(w,B);let j=le.enabled===!0&&le.isPresenting===!0,Z=F!==null&&(ce===null||j)&&F.begin(N,ce);if(w.matrixWorldAutoUpdate===!0&&w.updateMatrixWorld(),B.parent===null&&B.matrixWorldAutoUpdate===!0&&B.updateMatrixWorld(),le.enabled===!0&&le.isPresenting===!0&&(F===null||F.isCompositing()===!1)&&(le.cameraAutoUpdate===!0&&le.updateCamera(B),B=le.getCamera()),w.isScene===!0&&w.onBeforeRender(N,w,B,ce),A=te.get(w,E.length),A.init(B),A.state.textureUnits=Ze.getTextureUnits(),E.push(A),Ot.multiplyMatrices(B.projectionMatrix,B.matrixWorldInverse),B.isArrayCamera?Qt.setFromArrayCamera(B):rt.setFromProjectionMatrix(Ot,Di,B.reversedDepth),mn=this.localClippingEnabled,Xt=ie.init(this.clippingPlanes,mn),R=xe.get(w,_.length),R.init(),_.push(R),this.info.render.frame++,le.enabled===!0&&le.isPresenting===!0){let Ce=N.xr.getDepthSensingMesh();Ce!==null&&Er(Ce,B,-1/0,N.sortObjects)}Er(w,B,0,N.sortObjects),R.finish(),k!==null&&k.updateLights(A.state.lightsArray),N.sortObjects===!0&&R.sort(Xe,ot),sn=le.enabled===!1||le.isPresenting===!1||le.hasDepthSensing()===!1,sn&&U.addToRenderList(R,w),this.info.autoReset===!0&&this.info.reset(),Xt===!0&&ie.beginShadows();let $=A.state.shadowsArray;if(pe.render($,w,B),Xt===!0&&ie.endShadows(),(Z&&F.hasRenderPass())===!1){let Ce=R.opaque,Te=R.transmissive;if(A.setupLights(),B.isArrayCamera){let Ne=B.cameras;if(Te.length>0)for(let Ve=0,nt=Ne.length;Ve<nt;Ve++){let mt=Ne[Ve];Bi(Ce,Te,w,mt)}sn&&U.render(w);for(let Ve=0,nt=Ne.length;Ve<nt;Ve++){let mt=Ne[Ve];ma(R,w,mt,mt.viewport)}}else Te.length>0&&Bi(Ce,Te,w,B),sn&&U.render(w),ma(R,w,B)}ce!==null&&z===0&&(Ze.updateMultisampleRenderTarget(ce),Ze.updateRenderTargetMipmap(ce)),Z&&F.end(N),w.isScene===!0&&w.onAfterRender(N,w,B),ve.resetDefaultState(),J=-1,Q=null,E.pop(),E.length>0?(A=E[E.length-1],Ze.setTextureUnits(A.state.textureUnits),Xt===!0&&ie.setGlobalState(N.clippingPlanes,A.state.camera)):A=null,_.pop(),_.length>0?R=_[_.length-1]:R=null,k!==null&&k.renderEnd()};function Er(w,B,j,Z){if(w.visible===!1)return;if(w.layers.test(B.layers)){if(w.isGroup)j=w.renderOrder;else if(w.isLOD)w.autoUpdate===!0&&w.update(B);else if(w.isLight)A.pushLight(w),w.castShadow&&A.pushShadow(w);else if(w.isSprite){let Ce=B.isArrayCamera?Qt:rt;if(!w.frustumCulled||w.intersectsFrustum(Ce)){Z&&wt.setFromMatrixPosition(w.matrixWorld).applyMatrix4(Ot);let Te=ue.update(w),Ne=w.material;Ne.visible&&R.push(w,Te,Ne,j,wt.z,null,B)}}else if(w.isMesh||w.isLine||w.isPoints){let Ce=B.isArrayCamera?Qt:rt;if(!w.frustumCulled||w.intersectsFrustum(Ce)){let Te=ue.update(w),Ne=w.material;if(Z&&(w.boundingSphere!==void 0?(w.boundingSphere===null&&w.computeBoundingSphere(),wt.copy(w.boundingSphere.center)):(Te.boundingSphere===null&&Te.computeBoundingSphere(),wt.copy(Te.boundingSphere.center)),wt.applyMatrix4(w.matrixWorld).applyMatrix4(Ot)),Array.isArray(Ne)){let Ve=Te.groups;for(let nt=0,mt=Ve.length;nt<mt;nt++){let ke=Ve[nt],gt=Ne[ke.materialIndex];gt&&gt.visible&&R.push(w,Te,gt,j,wt.z,ke,B)}}else Ne.visible&&R.push(w,Te,Ne,j,wt.z,null,B)}}}let we=w.children;for(let Ce=0,Te=we.length;Ce<Te;Ce++)Er(we[Ce],B,j,Z)}function ma(w,B,j,Z){let{opaque:$,transmissive:we,transparent:Ce}=w;A.setupLightsView(j),Xt===!0&&ie.setGlobalState(N.clippingPlanes,j),Z&&Ee.viewport(re.copy(Z)),$.length>0&&on($,B,j),we.length>0&&on(we,B,j),Ce.length>0&&on(Ce,B,j),Ee.buffers.depth.setTest(!0),Ee.buffers.depth.setMask(!0),Ee.buffers.color.setMask(!0),Ee.setPolygonOffset(!1)}function Bi(w,B,j,Z){if((j.isScene===!0?j.overrideMaterial:null)!==null)return;if(A.state.transmissionRenderTarget[Z.id]===void 0){let ke=qe.has("EXT_color_buffer_half_float")||qe.has("EXT_color_buffer_float");A.state.transmissionRenderTarget[Z.id]=new wi(1,1,{generateMipmaps:!0,type:ke?Qi:li,minFilter:Hr,samples:Math.max(4,at.samples),stencilBuffer:s,resolveDepthBuffer:!1,resolveStencilBuffer:!1,storeMultisampledDepthBuffer:!1,storeMultisampledStencilBuffer:!1,colorSpace:St.workingColorSpace})}let we=A.state.transmissionRenderTarget[Z.id],Ce=Z.viewport||re;we.setSize(Ce.z*N.transmissionResolutionScale,Ce.w*N.transmissionResolutionScale);let Te=N.getRenderTarget(),Ne=N.getActiveCubeFace(),Ve=N.getActiveMipmapLevel();N.setRenderTarget(we),N.getClearColor(ee),me=N.getClearAlpha(),me<1&&N.setClearColor(16777215,.5),N.clear(),sn&&U.render(j);let nt=N.toneMapping;N.toneMapping=xr;let mt=Z.viewport;if(Z.viewport!==void 0&&(Z.viewport=void 0),A.setupLightsView(Z),Xt===!0&&ie.setGlobalState(N.clippingPlanes,Z),on(w,j,Z),Ze.updateMultisampleRenderTarget(we),Ze.updateRenderTargetMipmap(we),qe.has("WEBGL_multisampled_render_to_texture")===!1){let ke=!1;for(let gt=0,rn=B.length;gt<rn;gt++){let Dt=B[gt],{object:Ft,geometry:wn,material:Fe,group:_n}=Dt;if(Fe.side===yr&&Ft.layers.test(Z.layers)){let bt=Fe.side;Fe.side=si,Fe.needsUpdate=!0,fn(Ft,j,Z,wn,Fe,_n),Fe.side=bt,Fe.needsUpdate=!0,ke=!0}}ke===!0&&(Ze.updateMultisampleRenderTarget(we),Ze.updateRenderTargetMipmap(we))}N.setRenderTarget(Te,Ne,Ve),N.setClearColor(ee,me),mt!==void 0&&(Z.viewport=mt),N.toneMapping=nt}function on(w,B,j){let Z=B.isScene===!0?B.overrideMaterial:null;for(let $=0,we=w.length;$<we;$++){let Ce=w[$],{object:Te,geometry:Ne,group:Ve}=Ce,nt=Ce.material;nt.allowOverride===!0&&Z!==null&&(nt=Z),Te.layers.test(j.layers)&&fn(Te,B,j,Ne,nt,Ve)}}function fn(w,B,j,Z,$,we){k!==null&&$.isNodeMaterial&&k.setObject(w,$),w.onBeforeRender(N,B,j,Z,$,we),w.modelViewMatrix.multiplyMatrices(j.matrixWorldInverse,w.matrixWorld),w.normalMatrix.getNormalMatrix(w.modelViewMatrix),$.onBeforeRender(N,B,j,Z,w,we),$.transparent===!0&&$.side===yr&&$.forceSinglePass===!1?($.side=si,$.needsUpdate=!0,N.renderBufferDirect(j,B,Z,$,w,we),$.side=xs,$.needsUpdate=!0,N.renderBufferDirect(j,B,Z,$,w,we),$.side=yr):N.renderBufferDirect(j,B,Z,$,w,we),w.onAfterRender(N,B,j,Z,$,we)}function dn(w){let B=0;for(let j of w)j.texture!==null&&B++;return B}function rr(w,B,j){B.isScene!==!0&&(B=Mn);let Z=Ge.get(w),$=A.state.lights,we=A.state.shadowsArray,Ce=$.state.version,Te=oe.getParameters(w,$.state,we,B,j,A.state.lightProbeGridArray),Ne=oe.getProgramCacheKey(Te),Ve=Z.programs;Z.environment=w.isMeshStandardMaterial||w.isMeshLambertMaterial||w.isMeshPhongMaterial?B.environment:null,Z.fog=B.fog;let nt=w.isMeshStandardMaterial||w.isMeshLambertMaterial&&!w.envMap||w.isMeshPhongMaterial&&!w.envMap;Z.envMap=I.get(w.envMap||Z.environment,nt),Z.envMapRotation=Z.environment!==null&&w.envMap===null?B.environmentRotation:w.envMapRotation,Ve===void 0&&(w.addEventListener("dispose",lt),Ve=new Map,Z.programs=Ve,Z.programVariants=new Map);let mt=Ve.get(Ne);if(mt!==void 0){if(Z.currentProgram===mt&&Z.lightsStateVersion===Ce)return ga(w,Te),mt}else Te.uniforms=oe.getUniforms(w),k!==null&&w.isNodeMaterial&&k.build(w,j,Te),w.onBeforeCompile(Te,N),mt=oe.acquireProgram(Te,Ne),Ve.set(Ne,mt),Z.uniforms=Te.uniforms;let ke=Z.uniforms;return(!w.isShaderMaterial&&!w.isRawShaderMaterial||w.clipping===!0)&&(ke.clippingPlanes=ie.uniform),ga(w,Te),Z.needsLights=qr(w),Z.lightsStateVersion=Ce,Z.needsLights&&(ke.ambientLightColor.value=$.state.ambient,ke.lightProbe.value=$.state.probe,ke.sunLights.value=$.state.sun,ke.sunLightShadows.value=$.state.sunShadow,ke.directionalLights.value=$.state.directional,ke.directionalLightShadows.value=$.state.directionalShadow,ke.spotLights.value=$.state.spot,ke.spotLightShadows.value=$.state.spotShadow,ke.rectAreaLights.value=$.state.rectArea,ke.ltc_1.value=$.state.rectAreaLTC1,ke.ltc_2.value=$.state.rectAreaLTC2,ke.pointLights.value=$.state.point,ke.pointLightShadows.value=$.state.pointShadow,ke.hemisphereLights.value=$.state.hemi,ke.sunShadowMatrix.value=$.state.sunShadowMatrix,ke.sunShadowCascade.value=$.state.sunShadowCascade,ke.directionalShadowMatrix.value=$.state.directionalShadowMatrix,ke.spotLightMatrix.value=$.state.spotLightMatrix,ke.spotLightMap.value=$.state.spotLightMap,ke.pointShadowMatrix.value=$.state.pointShadowMatrix),Z.numLightProbeGrids=dn(A.state.lightProbeGridArray),Z.currentProgram=mt,Z.uniformsList=null,mt}function hi(w,B,j,Z,$){let we=Ge.get(w),Ce=we.currentProgram.id+","+Z+","+$,Te=we.programVariants.get(Ce);return Te===void 0?(Te=rr(w,B,j),we.programVariants.set(Ce,Te)):(we.currentProgram=Te,we.uniformsList=null,we.outputColorSpace=Z,we.toneMapping=$),Te}function $r(w){if(w.uniformsList===null){let B=w.currentProgram.getUniforms();w.uniformsList=oa.seqWithValue(B.seq,w.uniforms)}return w.uniformsList}function ga(w,B){let j=Ge.get(w);j.outputColorSpace=B.outputColorSpace,j.batching=B.batching,j.batchingColor=B.batchingColor,j.instancing=B.instancing,j.instancingColor=B.instancingColor,j.instancingMorph=B.instancingMorph,j.skinning=B.skinning,j.morphTargets=B.morphTargets,j.morphNormals=B.morphNormals,j.morphColors=B.morphColors,j.morphTargetsCount=B.morphTargetsCount,j.numClippingPlanes=B.numClippingPlanes,j.numIntersection=B.numClipIntersection,j.vertexAlphas=B.vertexAlphas,j.vertexTangents=B.vertexTangents,j.toneMapping=B.toneMapping}function _a(w,B,j,Z,$){B.isScene!==!0&&(B=Mn),Ze.resetTextureUnits();let we=B.fog,Ce=Z.isMeshStandardMaterial||Z.isMeshLambertMaterial||Z.isMeshPhongMaterial?B.environment:null,Te=ce===null?N.outputColorSpace:ce.isXRRenderTarget===!0?ce.texture.colorSpace:St.workingColorSpace,Ne=Z.isMeshStandardMaterial||Z.isMeshLambertMaterial&&!Z.envMap||Z.isMeshPhongMaterial&&!Z.envMap,Ve=I.get(Z.envMap||Ce,Ne),nt=Z.vertexColors===!0&&!!j.attributes.color&&j.attributes.color.itemSize===4,mt=!!j.attributes.tangent&&(!!Z.normalMap||Z.anisotropy>0),ke=!!j.morphAttributes.position,gt=!!j.morphAttributes.normal,rn=!!j.morphAttributes.color,Dt=xr;Z.toneMapped&&(ce===null||ce.isXRRenderTarget===!0)&&(Dt=N.toneMapping);let Ft=j.morphAttributes.position||j.morphAttributes.normal||j.morphAttributes.color,wn=Ft!==void 0?Ft.length:0,Fe=Ge.get(Z),_n=A.state.lights;if(Xt===!0&&(mn===!0||w!==Q)){let Ut=w===Q&&Z.id===J;ie.setState(Z,w,Ut)}let bt=!1,Mr=!1;Z.version===Fe.__version?Fe.needsLights&&Fe.lightsStateVersion!==_n.state.version||$.isBatchedMesh&&Fe.batching===!1||!$.isBatchedMesh&&Fe.batching===!0||$.isBatchedMesh&&Fe.batchingColor===!0&&$._colorsTexture===null||$.isBatchedMesh&&Fe.batchingColor===!1&&$._colorsTexture!==null||$.isInstancedMesh&&Fe.instancing===!1||!$.isInstancedMesh&&Fe.instancing===!0||$.isSkinnedMesh&&Fe.skinning===!1||!$.isSkinnedMesh&&Fe.skinning===!0||$.isInstancedMesh&&Fe.instancingColor===!0&&$.instanceColor===null||$.isInstancedMesh&&Fe.instancingColor===!1&&$.instanceColor!==null||$.isInstancedMesh&&Fe.instancingMorph===!0&&$.morphTexture===null||$.isInstancedMesh&&Fe.instancingMorph===!1&&$.morphTexture!==null||Fe.envMap!==Ve||Z.fog===!0&&Fe.fog!==we||Fe.numClippingPlanes!==void 0&&(Fe.numClippingPlanes!==ie.numPlanes||Fe.numIntersection!==ie.numIntersection)||Fe.vertexAlphas!==nt||Fe.vertexTangents!==mt||Fe.morphTargets!==ke||Fe.morphNormals!==gt||Fe.morphColors!==rn||Fe.morphTargetsCount!==wn||Fe.numLightProbeGrids!==dn(A.state.lightProbeGridArray)?bt=!0:(Fe.outputColorSpace!==Te||Fe.toneMapping!==Dt)&&(Mr=!0):(bt=!0,Fe.__version=Z.version);let yn=Fe.currentProgram;(bt===!0||Mr===!0)&&(yn=Mr===!0?hi(Z,B,$,Te,Dt):rr(Z,B,$),k&&Z.isNodeMaterial&&k.onUpdateProgram(Z,yn,Fe));let qs=!1,sr=!1,wr=!1,ut=yn.getUniforms(),an=Fe.uniforms;if(Ee.useProgram(yn.program)&&(qs=!0,sr=!0,wr=!0),Z.id!==J&&(J=Z.id,sr=!0),qs||Q!==w){Ee.buffers.depth.getReversed()&&w.reversedDepth!==!0&&(w._reversedDepth=!0,w.updateProjectionMatrix()),ut.setValue(O,"projectionMatrix",w.projectionMatrix),ut.setValue(O,"viewMatrix",w.matrixWorldInverse);let xn=ut.map.cameraPosition;xn!==void 0&&xn.setValue(O,Ln.setFromMatrixPosition(w.matrixWorld)),at.logarithmicDepthBuffer&&ut.setValue(O,"logDepthBufFC",2/(Math.log(w.far+1)/Math.LN2)),(Z.isMeshPhongMaterial||Z.isMeshToonMaterial||Z.isMeshLambertMaterial||Z.isMeshBasicMaterial||Z.isMeshStandardMaterial||Z.isShaderMaterial)&&ut.setValue(O,"isOrthographic",w.isOrthographicCamera===!0),Q!==w&&(Q=w,sr=!0,wr=!0)}if(Fe.needsLights&&(_n.state.sunShadowMap.length>0&&ut.setValue(O,"sunShadowMap",_n.state.sunShadowMap,Ze),_n.state.directionalShadowMap.length>0&&ut.setValue(O,"directionalShadowMap",_n.state.directionalShadowMap,Ze),_n.state.spotShadowMap.length>0&&ut.setValue(O,"spotShadowMap",_n.state.spotShadowMap,Ze),_n.state.pointShadowMap.length>0&&ut.setValue(O,"pointShadowMap",_n.state.pointShadowMap,Ze)),$.isSkinnedMesh){ut.setOptional(O,$,"bindMatrix"),ut.setOptional(O,$,"bindMatrixInverse");let Ut=$.skeleton;Ut&&(Ut.boneTexture===null&&Ut.computeBoneTexture(),ut.setValue(O,"boneTexture",Ut.boneTexture,Ze))}$.isBatchedMesh&&(ut.setOptional(O,$,"batchingTexture"),ut.setValue(O,"batchingTexture",$._matricesTexture,Ze),ut.setOptional(O,$,"batchingIdTexture"),ut.setValue(O,"batchingIdTexture",$._indirectTexture,Ze),ut.setOptional(O,$,"batchingColorTexture"),$._colorsTexture!==null&&ut.setValue(O,"batchingColorTexture",$._colorsTexture,Ze));let jn=j.morphAttributes;if((jn.position!==void 0||jn.normal!==void 0||jn.color!==void 0)&&se.update($,j,yn),(sr||Fe.receiveShadow!==$.receiveShadow)&&(Fe.receiveShadow=$.receiveShadow,ut.setValue(O,"receiveShadow",$.receiveShadow)),(Z.isMeshStandardMaterial||Z.isMeshLambertMaterial||Z.isMeshPhongMaterial)&&Z.envMap===null&&B.environment!==null&&(an.envMapIntensity.value=B.environmentIntensity),an.dfgLUT!==void 0&&(an.dfgLUT.value=BN()),sr){if(ut.setValue(O,"toneMappingExposure",N.toneMappingExposure),Fe.needsLights&&Ks(an,wr),we&&Z.fog===!0&&_e.refreshFogUniforms(an,we),_e.refreshMaterialUniforms(an,Z,Se,Ae,A.state.transmissionRenderTarget[w.id]),Fe.needsLights&&Fe.numLightProbeGrids>0){let Ut=v,xn=0;for(let Yn of A.state.lightProbeGridArray)Yn.texture!==null&&(Ut.textures[xn]=Yn.texture,Ut.min[xn]=Yn.boundingBox.min,Ut.max[xn]=Yn.boundingBox.max,Ut.resolution[xn]=Yn.resolution,xn++);for(let Yn in Ut)Ut[Yn].length=xn;an.probesSH.value=Ut.textures,an.probesMin.value=Ut.min,an.probesMax.value=Ut.max,an.probesResolution.value=Ut.resolution}oa.upload(O,$r(Fe),an,Ze)}if(Z.isShaderMaterial&&Z.uniformsNeedUpdate===!0&&(oa.upload(O,$r(Fe),an,Ze),Z.uniformsNeedUpdate=!1),Z.isSpriteMaterial&&ut.setValue(O,"center",$.center),ut.setValue(O,"modelViewMatrix",$.modelViewMatrix),ut.setValue(O,"normalMatrix",$.normalMatrix),ut.setValue(O,"modelMatrix",$.matrixWorld),Z.uniformsGroups!==void 0){let Ut=Z.uniformsGroups;for(let xn=0,Yn=Ut.length;xn<Yn;xn++){let Hl=Ut[xn];He.update(Hl,yn),He.bind(Hl,yn)}}return yn}function Ks(w,B){w.ambientLightColor.needsUpdate=B,w.lightProbe.needsUpdate=B,w.sunLights.needsUpdate=B,w.sunLightShadows.needsUpdate=B,w.directionalLights.needsUpdate=B,w.directionalLightShadows.needsUpdate=B,w.pointLights.needsUpdate=B,w.pointLightShadows.needsUpdate=B,w.spotLights.needsUpdate=B,w.spotLightShadows.needsUpdate=B,w.rectAreaLights.needsUpdate=B,w.hemisphereLights.needsUpdate=B}function qr(w){return w.isMeshLambertMaterial||w.isMeshToonMaterial||w.isMeshPhongMaterial||w.isMeshStandardMaterial||w.isShadowMaterial||w.isShaderMaterial&&w.lights===!0}this.getActiveCubeFace=function(){return K},this.getActiveMipmapLevel=function(){return z},this.getRenderTarget=function(){return ce},this.setRenderTargetTextures=function(w,B,j){let Z=Ge.get(w);Z.__autoAllocateDepthBuffer=w.resolveDepthBuffer===!1,Z.__autoAllocateDepthBuffer===!1&&(Z.__useRenderToTexture=!1),Ge.get(w.texture).__webglTexture=B,Ge.get(w.depthTexture).__webglTexture=Z.__autoAllocateDepthBuffer?void 0:j,Z.__hasExternalTextures=!0},this.setRenderTargetFramebuffer=function(w,B){let j=Ge.get(w);j.__webglFramebuffer=B,j.__useDefaultFramebuffer=B===void 0},this.setRenderTarget=function(w,B=0,j=0){ce=w,K=B,z=j;let Z=null,$=!1,we=!1;if(w){let Te=Ge.get(w);if(Te.__useDefaultFramebuffer!==void 0){Ee.bindFramebuffer(O.FRAMEBUFFER,Te.__webglFramebuffer),re.copy(w.viewport),fe.copy(w.scissor),he=w.scissorTest,Ee.viewport(re),Ee.scissor(fe),Ee.setScissorTest(he),J=-1;return}else if(Te.__webglFramebuffer===void 0)Ze.setupRenderTarget(w);else if(Te.__hasExternalTextures)Ze.rebindTextures(w,Ge.get(w.texture).__webglTexture,Ge.get(w.depthTexture).__webglTexture);else if(w.depthBuffer){let nt=w.depthTexture;if(Te.__boundDepthTexture!==nt){if(nt!==null&&Ge.has(nt)&&(w.width!==nt.image.width||w.height!==nt.image.height))throw new Error("THREE.WebGLRenderer: Attached DepthTexture is initialized to the incorrect size.");Ze.setupDepthRenderbuffer(w)}}let Ne=w.texture;(Ne.isData3DTexture||Ne.isDataArrayTexture||Ne.isCompressedArrayTexture)&&(we=!0);let Ve=Ge.get(w).__webglFramebuffer;w.isWebGLCubeRenderTarget?(Array.isArray(Ve[B])?Z=Ve[B][j]:Z=Ve[B],$=!0):w.samples>0&&Ze.useMultisampledRTT(w)===!1?Z=Ge.get(w).__webglMultisampledFramebuffer:Array.isArray(Ve)?Z=Ve[j]:Z=Ve,re.copy(w.viewport),fe.copy(w.scissor),he=w.scissorTest}else re.copy(ze).multiplyScalar(Se).floor(),fe.copy(ft).multiplyScalar(Se).floor(),he=ct;if(j!==0&&(Z=H),Ee.bindFramebuffer(O.FRAMEBUFFER,Z)&&Ee.drawBuffers(w,Z),Ee.viewport(re),Ee.scissor(fe),Ee.setScissorTest(he),$){let Te=Ge.get(w.texture);O.framebufferTexture2D(O.FRAMEBUFFER,O.COLOR_ATTACHMENT0,O.TEXTURE_CUBE_MAP_POSITIVE_X+B,Te.__webglTexture,j)}else if(we){let Te=B;for(let Ne=0;Ne<w.textures.length;Ne++){let Ve=Ge.get(w.textures[Ne]);O.framebufferTextureLayer(O.FRAMEBUFFER,O.COLOR_ATTACHMENT0+Ne,Ve.__webglTexture,j,Te)}}else if(w!==null&&j!==0){let Te=Ge.get(w.texture);O.framebufferTexture2D(O.FRAMEBUFFER,O.COLOR_ATTACHMENT0,O.TEXTURE_2D,Te.__webglTexture,j)}J=-1};function $s(w){let B=Ge.get(w);return(B.__readFormat!==w.format||B.__readType!==w.type)&&(B.__readFormat=w.format,B.__readType=w.type,B.__formatReadable=at.textureFormatReadable(w.format),B.__typeReadable=at.textureTypeReadable(w.type)),B}this.readRenderTargetPixels=function(w,B,j,Z,$,we,Ce,Te=0){if(!(w&&w.isWebGLRenderTarget)){et("WebGLRenderer.readRenderTargetPixels: renderTarget is not THREE.WebGLRenderTarget.");return}let Ne=Ge.get(w).__webglFramebuffer;if(w.isWebGLCubeRenderTarget&&Ce!==void 0&&(Ne=Ne[Ce],Array.isArray(Ne)&&(Ne=Ne[0])),Ne){Ee.bindFramebuffer(O.FRAMEBUFFER,Ne);try{let Ve=w.textures[Te],nt=Ve.format,mt=Ve.type;w.textures.length>1&&O.readBuffer(O.COLOR_ATTACHMENT0+Te);let ke=$s(Ve);if(ke.__formatReadable===!1){et("WebGLRenderer.readRenderTargetPixels: renderTarget is not in RGBA or implementation defined format.");return}if(ke.__typeReadable===!1){et("WebGLRenderer.readRenderTargetPixels: renderTarget is not in UnsignedByteType or implementation defined type.");return}B>=0&&B<=w.width-Z&&j>=0&&j<=w.height-$&&O.readPixels(B,j,Z,$,ge.convert(nt),ge.convert(mt),we)}finally{let Ve=ce!==null?Ge.get(ce).__webglFramebuffer:null;Ee.bindFramebuffer(O.FRAMEBUFFER,Ve)}}},this.readRenderTargetPixelsAsync=async function(w,B,j,Z,$,we,Ce,Te=0){if(!(w&&w.isWebGLRenderTarget))throw new Error("THREE.WebGLRenderer.readRenderTargetPixels: renderTarget is not THREE.WebGLRenderTarget.");let Ne=Ge.get(w).__webglFramebuffer;if(w.isWebGLCubeRenderTarget&&Ce!==void 0&&(Ne=Ne[Ce],Array.isArray(Ne)&&(Ne=Ne[0])),Ne)if(B>=0&&B<=w.width-Z&&j>=0&&j<=w.height-$){Ee.bindFramebuffer(O.FRAMEBUFFER,Ne);let Ve=w.textures[Te],nt=Ve.format,mt=Ve.type;w.textures.length>1&&O.readBuffer(O.COLOR_ATTACHMENT0+Te);let ke=$s(Ve);if(ke.__formatReadable===!1)throw new Error("THREE.WebGLRenderer.readRenderTargetPixelsAsync: renderTarget is not in RGBA or implementation defined format.");if(ke.__typeReadable===!1)throw new Error("THREE.WebGLRenderer.readRenderTargetPixelsAsync: renderTarget is not in UnsignedByteType or implementation defined type.");let gt=O.createBuffer();O.bindBuffer(O.PIXEL_PACK_BUFFER,gt),O.bufferData(O.PIXEL_PACK_BUFFER,we.byteLength,O.STREAM_READ),O.readPixels(B,j,Z,$,ge.convert(nt),ge.convert(mt),0),O.bindBuffer(O.PIXEL_PACK_BUFFER,null);let rn=ce!==null?Ge.get(ce).__webglFramebuffer:null;Ee.bindFramebuffer(O.FRAMEBUFFER,rn);let Dt=O.fenceSync(O.SYNC_GPU_COMMANDS_COMPLETE,0);return O.flush(),await Yb(O,Dt,4),O.bindBuffer(O.PIXEL_PACK_BUFFER,gt),O.getBufferSubData(O.PIXEL_PACK_BUFFER,0,we),O.bindBuffer(O.PIXEL_PACK_BUFFER,null),O.deleteBuffer(gt),O.deleteSync(Dt),we}else throw new Error("THREE.WebGLRenderer.readRenderTargetPixelsAsync: requested read bounds are out of range.")},this.copyFramebufferToTexture=function(w,B=null,j=0){let Z=Math.pow(2,-j),$=Math.floor(w.image.width*Z),we=Math.floor(w.image.height*Z),Ce=B!==null?B.x:0,Te=B!==null?B.y:0;Ze.setTexture2D(w,0),O.copyTexSubImage2D(O.TEXTURE_2D,j,0,0,Ce,Te,$,we),Ee.unbindTexture()},this.copyTextureToTexture=function(w,B,j=null,Z=null,$=0,we=0){let Ce,Te,Ne,Ve,nt,mt,ke,gt,rn,Dt=w.isCompressedTexture?w.mipmaps[we]:w.image;if(j!==null)Ce=j.max.x-j.min.x,Te=j.max.y-j.min.y,Ne=j.isBox3?j.max.z-j.min.z:1,Ve=j.min.x,nt=j.min.y,mt=j.isBox3?j.min.z:0;else{let ut=Math.pow(2,-$);Ce=Math.floor(Dt.width*ut),Te=Math.floor(Dt.height*ut),w.isDataArrayTexture?Ne=Dt.depth:w.isData3DTexture?Ne=Math.floor(Dt.depth*ut):Ne=1,Ve=0,nt=0,mt=0}Z!==null?(ke=Z.x,gt=Z.y,rn=Z.z):(ke=0,gt=0,rn=0);let Ft=ge.convert(B.format),wn=ge.convert(B.type),Fe;B.isData3DTexture?(Ze.setTexture3D(B,0),Fe=O.TEXTURE_3D):B.isDataArrayTexture||B.isCompressedArrayTexture?(Ze.setTexture2DArray(B,0),Fe=O.TEXTURE_2D_ARRAY):(Ze.setTexture2D(B,0),Fe=O.TEXTURE_2D),Ee.activeTexture(O.TEXTURE0),Ee.pixelStorei(O.UNPACK_FLIP_Y_WEBGL,B.flipY),Ee.pixelStorei(O.UNPACK_PREMULTIPLY_ALPHA_WEBGL,B.premultiplyAlpha),Ee.pixelStorei(O.UNPACK_ALIGNMENT,B.unpackAlignment);let _n=Ee.getParameter(O.UNPACK_ROW_LENGTH),bt=Ee.getParameter(O.UNPACK_IMAGE_HEIGHT),Mr=Ee.getParameter(O.UNPACK_SKIP_PIXELS),yn=Ee.getParameter(O.UNPACK_SKIP_ROWS),qs=Ee.getParameter(O.UNPACK_SKIP_IMAGES);Ee.pixelStorei(O.UNPACK_ROW_LENGTH,Dt.width),Ee.pixelStorei(O.UNPACK_IMAGE_HEIGHT,Dt.height),Ee.pixelStorei(O.UNPACK_SKIP_PIXELS,Ve),Ee.pixelStorei(O.UNPACK_SKIP_ROWS,nt),Ee.pixelStorei(O.UNPACK_SKIP_IMAGES,mt);let sr=w.isDataArrayTexture||w.isData3DTexture,wr=B.isDataArrayTexture||B.isData3DTexture;if(w.isDepthTexture){let ut=Ge.get(w),an=Ge.get(B),jn=Ge.get(ut.__renderTarget),Ut=Ge.get(an.__renderTarget);Ee.bindFramebuffer(O.READ_FRAMEBUFFER,jn.__webglFramebuffer),Ee.bindFramebuffer(O.DRAW_FRAMEBUFFER,Ut.__webglFramebuffer);for(let xn=0;xn<Ne;xn++)sr&&(O.framebufferTextureLayer(O.READ_FRAMEBUFFER,O.COLOR_ATTACHMENT0,Ge.get(w).__webglTexture,$,mt+xn),O.framebufferTextureLayer(O.DRAW_FRAMEBUFFER,O.COLOR_ATTACHMENT0,Ge.get(B).__webglTexture,we,rn+xn)),O.blitFramebuffer(Ve,nt,Ve+Ce,nt+Te,ke,gt,ke+Ce,gt+Te,O.DEPTH_BUFFER_BIT,O.NEAREST);Ee.bindFramebuffer(O.READ_FRAMEBUFFER,null),Ee.bindFramebuffer(O.DRAW_FRAMEBUFFER,null)}else if($!==0||w.isRenderTargetTexture||Ge.has(w)){let ut=Ge.get(w),an=Ge.get(B);Ee.bindFramebuffer(O.READ_FRAMEBUFFER,D),Ee.bindFramebuffer(O.DRAW_FRAMEBUFFER,W);for(let jn=0;jn<Ne;jn++)sr?O.framebufferTextureLayer(O.READ_FRAMEBUFFER,O.COLOR_ATTACHMENT0,ut.__webglTexture,$,mt+jn):O.framebufferTexture2D(O.READ_FRAMEBUFFER,O.COLOR_ATTACHMENT0,O.TEXTURE_2D,ut.__webglTexture,$),wr?O.framebufferTextureLayer(O.DRAW_FRAMEBUFFER,O.COLOR_ATTACHMENT0,an.__webglTexture,we,rn+jn):O.framebufferTexture2D(O.DRAW_FRAMEBUFFER,O.COLOR_ATTACHMENT0,O.TEXTURE_2D,an.__webglTexture,we),$!==0?O.blitFramebuffer(Ve,nt,Ve+Ce,nt+Te,ke,gt,ke+Ce,gt+Te,O.COLOR_BUFFER_BIT,O.NEAREST):wr?O.copyTexSubImage3D(Fe,we,ke,gt,rn+jn,Ve,nt,Ce,Te):O.copyTexSubImage2D(Fe,we,ke,gt,Ve,nt,Ce,Te);Ee.bindFramebuffer(O.READ_FRAMEBUFFER,null),Ee.bindFramebuffer(O.DRAW_FRAMEBUFFER,null)}else wr?w.isDataTexture||w.isData3DTexture?O.texSubImage3D(Fe,we,ke,gt,rn,Ce,Te,Ne,Ft,wn,Dt.data):B.isCompressedArrayTexture?O.compressedTexSubImage3D(Fe,we,ke,gt,rn,Ce,Te,Ne,Ft,Dt.data):O.texSubImage3D(Fe,we,ke,gt,rn,Ce,Te,Ne,Ft,wn,Dt):w.isDataTexture?O.texSubImage2D(O.TEXTURE_2D,we,ke,gt,Ce,Te,Ft,wn,Dt.data):w.isCompressedTexture?O.compressedTexSubImage2D(O.TEXTURE_2D,we,ke,gt,Dt.width,Dt.height,Ft,Dt.data):O.texSubImage2D(O.TEXTURE_2D,we,ke,gt,Ce,Te,Ft,wn,Dt);Ee.pixelStorei(O.UNPACK_ROW_LENGTH,_n),Ee.pixelStorei(O.UNPACK_IMAGE_HEIGHT,bt),Ee.pixelStorei(O.UNPACK_SKIP_PIXELS,Mr),Ee.pixelStorei(O.UNPACK_SKIP_ROWS,yn),Ee.pixelStorei(O.UNPACK_SKIP_IMAGES,qs),we===0&&B.generateMipmaps===!0&&B.mipmapsAutoUpdate===!0&&O.generateMipmap(Fe),Ee.unbindTexture()},this.initRenderTarget=function(w){Ge.get(w).__webglFramebuffer===void 0&&Ze.setupRenderTarget(w)},this.initTexture=function(w){w.isCubeTexture?Ze.setTextureCube(w,0):w.isData3DTexture?Ze.setTexture3D(w,0):w.isDataArrayTexture||w.isCompressedArrayTexture?Ze.setTexture2DArray(w,0):Ze.setTexture2D(w,0),Ee.unbindTexture()},this.resetState=function(){K=0,z=0,ce=null,Ee.reset(),ve.reset()},typeof __THREE_DEVTOOLS__<"u"&&__THREE_DEVTOOLS__.dispatchEvent(new CustomEvent("observe",{detail:this}))}get coordinateSystem(){return Di}get outputColorSpace(){return this._outputColorSpace}set outputColorSpace(e){this._outputColorSpace=e;let t=this.getContext();t.drawingBufferColorSpace=St._getDrawingBufferColorSpace(e),t.unpackColorSpace=St._getUnpackColorSpace()}};var Lv={type:"change"},Rm={type:"start"},Fv={type:"end"},Qh=new us,Dv=new Ei,kN=Math.cos(70*sa.DEG2RAD),Nn=new X,ci=2*Math.PI,Nt={NONE:-1,ROTATE:0,DOLLY:1,PAN:2,TOUCH_ROTATE:3,TOUCH_PAN:4,TOUCH_DOLLY_PAN:5,TOUCH_DOLLY_ROTATE:6},Am=1e-6,ef=class extends wl{constructor(e,t=null){super(e,t),this.state=Nt.NONE,this.target=new X,this.cursor=new X,this.minDistance=0,this.maxDistance=1/0,this.minZoom=0,this.maxZoom=1/0,this.minTargetRadius=0,this.maxTargetRadius=1/0,this.minPolarAngle=0,this.maxPolarAngle=Math.PI,this.minAzimuthAngle=-1/0,this.maxAzimuthAngle=1/0,this.enableDamping=!1,this.dampingFactor=.05,this.enableZoom=!0,this.zoomSpeed=1,this.enableRotate=!0,this.rotateSpeed=1,this.keyRotateSpeed=1,this.enablePan=!0,this.panSpeed=1,this.screenSpacePanning=!0,this.keyPanSpeed=7,this.zoomToCursor=!1,this.autoRotate=!1,this.autoRotateSpeed=2,this.keys={LEFT:"ArrowLeft",UP:"ArrowUp",RIGHT:"ArrowRight",BOTTOM:"ArrowDown"},this.mouseButtons={LEFT:_s.ROTATE,MIDDLE:_s.DOLLY,RIGHT:_s.PAN},this.touches={ONE:ys.ROTATE,TWO:ys.DOLLY_PAN},this.target0=this.target.clone(),this.position0=this.object.position.clone(),this.zoom0=this.object.zoom,this._cursorStyle="auto",this._domElementKeyEvents=null,this._lastPosition=new X,this._lastQuaternion=new Mi,this._lastTargetPosition=new X,this._quat=new Mi().setFromUnitVectors(e.up,new X(0,1,0)),this._quatInverse=this._quat.clone().invert(),this._spherical=new jo,this._sphericalDelta=new jo,this._scale=1,this._panOffset=new X,this._rotateStart=new Ke,this._rotateEnd=new Ke,this._rotateDelta=new Ke,this._panStart=new Ke,this._panEnd=new Ke,this._panDelta=new Ke,this._dollyStart=new Ke,this._dollyEnd=new Ke,this._dollyDelta=new Ke,this._dollyDirection=new X,this._mouse=new Ke,this._performCursorZoom=!1,this._pointers=[],this._pointerPositions={},this._controlActive=!1,this._onPointerMove=GN.bind(this),this._onPointerDown=VN.bind(this),this._onPointerUp=zN.bind(this),this._onContextMenu=$N.bind(this),this._onMouseWheel=XN.bind(this),this._onKeyDown=YN.bind(this),this._onTouchStart=ZN.bind(this),this._onTouchMove=KN.bind(this),this._onMouseDown=HN.bind(this),this._onMouseMove=WN.bind(this),this._interceptControlDown=qN.bind(this),this._interceptControlUp=JN.bind(this),this.domElement!==null&&this.connect(this.domElement),this.update()}set cursorStyle(e){this._cursorStyle=e,e==="grab"?this.domElement.style.cursor="grab":this.domElement.style.cursor="auto"}get cursorStyle(){return this._cursorStyle}connect(e){super.connect(e),this.domElement.addEventListener("pointerdown",this._onPointerDown),this.domElement.addEventListener("pointercancel",this._onPointerUp),this.domElement.addEventListener("contextmenu",this._onContextMenu),this.domElement.addEventListener("wheel",this._onMouseWheel,{passive:!1}),this.domElement.ownerDocument.addEventListener("keydown",this._interceptControlDown,{passive:!0,capture:!0}),this.domElement.style.touchAction="none"}disconnect(){this.state=Nt.NONE,this.domElement.removeEventListener("pointerdown",this._onPointerDown),this.domElement.ownerDocument.removeEventListener("pointermove",this._onPointerMove),this.domElement.ownerDocument.removeEventListener("pointerup",this._onPointerUp),this.domElement.removeEventListener("pointercancel",this._onPointerUp),this.domElement.removeEventListener("wheel",this._onMouseWheel),this.domElement.removeEventListener("contextmenu",this._onContextMenu),this.stopListenToKeyEvents(),this.domElement.ownerDocument.removeEventListener("keydown",this._interceptControlDown,{capture:!0}),this.domElement.ownerDocument.removeEventListener("keyup",this._interceptControlUp,{capture:!0}),this._controlActive=!1,this._pointers.length=0,this._pointerPositions={},this.domElement.style.touchAction="",this.domElement.style.cursor="auto"}dispose(){this.disconnect()}getPolarAngle(){return this._spherical.phi}getAzimuthalAngle(){return this._spherical.theta}getDistance(){return this.object.position.distanceTo(this.target)}listenToKeyEvents(e){e.addEventListener("keydown",this._onKeyDown),this._domElementKeyEvents=e}stopListenToKeyEvents(){this._domElementKeyEvents!==null&&(this._domElementKeyEvents.removeEventListener("keydown",this._onKeyDown),this._domElementKeyEvents=null)}saveState(){this.target0.copy(this.target),this.position0.copy(this.object.position),this.zoom0=this.object.zoom}reset(){this.target.copy(this.target0),this.object.position.copy(this.position0),this.object.zoom=this.zoom0,this.object.updateProjectionMatrix(),this.dispatchEvent(Lv),this.update(),this.state=Nt.NONE}pan(e,t){this._pan(e,t),this.update()}dollyIn(e){this._dollyIn(e),this.update()}dollyOut(e){this._dollyOut(e),this.update()}rotateLeft(e){this._rotateLeft(e),this.update()}rotateUp(e){this._rotateUp(e),this.update()}update(e=null){let t=this.object.position;Nn.copy(t).sub(this.target),Nn.applyQuaternion(this._quat),this._spherical.setFromVector3(Nn),this.autoRotate&&this.state===Nt.NONE&&this._rotateLeft(this._getAutoRotationAngle(e)),this.enableDamping?(this._spherical.theta+=this._sphericalDelta.theta*this.dampingFactor,this._spherical.phi+=this._sphericalDelta.phi*this.dampingFactor):(this._spherical.theta+=this._sphericalDelta.theta,this._spherical.phi+=this._sphericalDelta.phi);let i=this.minAzimuthAngle,r=this.maxAzimuthAngle;isFinite(i)&&isFinite(r)&&(i<-Math.PI?i+=ci:i>Math.PI&&(i-=ci),r<-Math.PI?r+=ci:r>Math.PI&&(r-=ci),i<=r?this._spherical.theta=Math.max(i,Math.min(r,this._spherical.theta)):this._spherical.theta=this._spherical.theta>(i+r)/2?Math.max(i,this._spherical.theta):Math.min(r,this._spherical.theta)),this._spherical.phi=Math.max(this.minPolarAngle,Math.min(this.maxPolarAngle,this._spherical.phi)),this._spherical.makeSafe(),this.enableDamping===!0?this.target.addScaledVector(this._panOffset,this.dampingFactor):this.target.add(this._panOffset),this.target.sub(this.cursor),this.target.clampLength(this.minTargetRadius,this.maxTargetRadius),this.target.add(this.cursor);let s=!1;if(this.zoomToCursor&&this._performCursorZoom||this.object.isOrthographicCamera)this._spherical.radius=this._clampDistance(this._spherical.radius);else{let o=this._spherical.radius;this._spherical.radius=this._clampDistance(this._spherical.radius*this._scale),s=o!=this._spherical.radius}if(Nn.setFromSpherical(this._spherical),Nn.applyQuaternion(this._quatInverse),t.copy(this.target).add(Nn),this.object.lookAt(this.target),this.enableDamping===!0?(this._sphericalDelta.theta*=1-this.dampingFactor,this._sphericalDelta.phi*=1-this.dampingFactor,this._panOffset.multiplyScalar(1-this.dampingFactor)):(this._sphericalDelta.set(0,0,0),this._panOffset.set(0,0,0)),this.zoomToCursor&&this._performCursorZoom){let o=null;if(this.object.isPerspectiveCamera){let a=Nn.length();o=this._clampDistance(a*this._scale);let l=a-o;this.object.position.addScaledVector(this._dollyDirection,l),this.object.updateMatrixWorld(),s=!!l}else if(this.object.isOrthographicCamera){let a=new X(this._mouse.x,this._mouse.y,0);a.unproject(this.object);let l=this.object.zoom;this.object.zoom=Math.max(this.minZoom,Math.min(this.maxZoom,this.object.zoom/this._scale)),this.object.updateProjectionMatrix(),s=l!==this.object.zoom;let c=new X(this._mouse.x,this._mouse.y,0);c.unproject(this.object),this.object.position.sub(c).add(a),this.object.updateMatrixWorld(),o=Nn.length()}else console.warn("WARNING: OrbitControls.js encountered an unknown camera type - zoom to cursor disabled."),this.zoomToCursor=!1;o!==null&&(this.screenSpacePanning?this.target.set(0,0,-1).transformDirection(this.object.matrix).multiplyScalar(o).add(this.object.position):(Qh.origin.copy(this.object.position),Qh.direction.set(0,0,-1).transformDirection(this.object.matrix),Math.abs(this.object.up.dot(Qh.direction))<kN?this.object.lookAt(this.target):(Dv.setFromNormalAndCoplanarPoint(this.object.up,this.target),Qh.intersectPlane(Dv,this.target))))}else if(this.object.isOrthographicCamera){let o=this.object.zoom;this.object.zoom=Math.max(this.minZoom,Math.min(this.maxZoom,this.object.zoom/this._scale)),o!==this.object.zoom&&(this.object.updateProjectionMatrix(),s=!0)}return this._scale=1,this._performCursorZoom=!1,s||this._lastPosition.distanceToSquared(this.object.position)>Am||8*(1-this._lastQuaternion.dot(this.object.quaternion))>Am||this._lastTargetPosition.distanceToSquared(this.target)>Am?(this.dispatchEvent(Lv),this._lastPosition.copy(this.object.position),this._lastQuaternion.copy(this.object.quaternion),this._lastTargetPosition.copy(this.target),!0):!1}_getAutoRotationAngle(e){return e!==null?ci/60*this.autoRotateSpeed*e:ci/60/60*this.autoRotateSpeed}_getZoomScale(e){let t=Math.abs(e*.01);return Math.pow(.95,this.zoomSpeed*t)}_rotateLeft(e){this._sphericalDelta.theta-=e}_rotateUp(e){this._sphericalDelta.phi-=e}_panLeft(e,t){Nn.setFromMatrixColumn(t,0),Nn.multiplyScalar(-e),this._panOffset.add(Nn)}_panUp(e,t){this.screenSpacePanning===!0?Nn.setFromMatrixColumn(t,1):(Nn.setFromMatrixColumn(t,0),Nn.crossVectors(this.object.up,Nn)),Nn.multiplyScalar(e),this._panOffset.add(Nn)}_pan(e,t){let i=this.domElement;if(this.object.isPerspectiveCamera){let r=this.object.position;Nn.copy(r).sub(this.target);let s=Nn.length();s*=Math.tan(this.object.fov/2*Math.PI/180),this._panLeft(2*e*s/i.clientHeight,this.object.matrix),this._panUp(2*t*s/i.clientHeight,this.object.matrix)}else this.object.isOrthographicCamera?(this._panLeft(e*(this.object.right-this.object.left)/this.object.zoom/i.clientWidth,this.object.matrix),this._panUp(t*(this.object.top-this.object.bottom)/this.object.zoom/i.clientHeight,this.object.matrix)):(console.warn("WARNING: OrbitControls.js encountered an unknown camera type - pan disabled."),this.enablePan=!1)}_dollyOut(e){this.object.isPerspectiveCamera||this.object.isOrthographicCamera?this._scale/=e:(console.warn("WARNING: OrbitControls.js encountered an unknown camera type - dolly/zoom disabled."),this.enableZoom=!1)}_dollyIn(e){this.object.isPerspectiveCamera||this.object.isOrthographicCamera?this._scale*=e:(console.warn("WARNING: OrbitControls.js encountered an unknown camera type - dolly/zoom disabled."),this.enableZoom=!1)}_updateZoomParameters(e,t){if(!this.zoomToCursor)return;this._performCursorZoom=!0;let i=this.domElement.getBoundingClientRect(),r=e-i.left,s=t-i.top,o=i.width,a=i.height;this._mouse.x=r/o*2-1,this._mouse.y=-(s/a)*2+1,this._dollyDirection.set(this._mouse.x,this._mouse.y,1).unproject(this.object).sub(this.object.position).normalize()}_clampDistance(e){return Math.max(this.minDistance,Math.min(this.maxDistance,e))}_handleMouseDownRotate(e){this._rotateStart.set(e.clientX,e.clientY)}_handleMouseDownDolly(e){this._updateZoomParameters(e.clientX,e.clientY),this._dollyStart.set(e.clientX,e.clientY)}_handleMouseDownPan(e){this._panStart.set(e.clientX,e.clientY)}_handleMouseMoveRotate(e){this._rotateEnd.set(e.clientX,e.clientY),this._rotateDelta.subVectors(this._rotateEnd,this._rotateStart).multiplyScalar(this.rotateSpeed);let t=this.domElement;this._rotateLeft(ci*this._rotateDelta.x/t.clientHeight),this._rotateUp(ci*this._rotateDelta.y/t.clientHeight),this._rotateStart.copy(this._rotateEnd),this.update()}_handleMouseMoveDolly(e){this._dollyEnd.set(e.clientX,e.clientY),this._dollyDelta.subVectors(this._dollyEnd,this._dollyStart),this._dollyDelta.y>0?this._dollyOut(this._getZoomScale(this._dollyDelta.y)):this._dollyDelta.y<0&&this._dollyIn(this._getZoomScale(this._dollyDelta.y)),this._dollyStart.copy(this._dollyEnd),this.zoomToCursor&&(this._performCursorZoom=!0,this._dollyDirection.set(this._mouse.x,this._mouse.y,1).unproject(this.object).sub(this.object.position).normalize()),this.update()}_handleMouseMovePan(e){this._panEnd.set(e.clientX,e.clientY),this._panDelta.subVectors(this._panEnd,this._panStart).multiplyScalar(this.panSpeed),this._pan(this._panDelta.x,this._panDelta.y),this._panStart.copy(this._panEnd),this.update()}_handleMouseWheel(e){this._updateZoomParameters(e.clientX,e.clientY),e.deltaY<0?this._dollyIn(this._getZoomScale(e.deltaY)):e.deltaY>0&&this._dollyOut(this._getZoomScale(e.deltaY)),this.update()}_handleKeyDown(e){let t=!1;switch(e.code){case this.keys.UP:e.ctrlKey||e.metaKey||e.shiftKey?this.enableRotate&&this._rotateUp(ci*this.keyRotateSpeed/this.domElement.clientHeight):this.enablePan&&this._pan(0,this.keyPanSpeed),t=!0;break;case this.keys.BOTTOM:e.ctrlKey||e.metaKey||e.shiftKey?this.enableRotate&&this._rotateUp(-ci*this.keyRotateSpeed/this.domElement.clientHeight):this.enablePan&&this._pan(0,-this.keyPanSpeed),t=!0;break;case this.keys.LEFT:e.ctrlKey||e.metaKey||e.shiftKey?this.enableRotate&&this._rotateLeft(ci*this.keyRotateSpeed/this.domElement.clientHeight):this.enablePan&&this._pan(this.keyPanSpeed,0),t=!0;break;case this.keys.RIGHT:e.ctrlKey||e.metaKey||e.shiftKey?this.enableRotate&&this._rotateLeft(-ci*this.keyRotateSpeed/this.domElement.clientHeight):this.enablePan&&this._pan(-this.keyPanSpeed,0),t=!0;break}t&&(e.preventDefault(),this.update())}_handleTouchStartRotate(e){if(this._pointers.length===1)this._rotateStart.set(e.pageX,e.pageY);else{let t=this._getSecondPointerPosition(e),i=.5*(e.pageX+t.x),r=.5*(e.pageY+t.y);this._rotateStart.set(i,r)}}_handleTouchStartPan(e){if(this._pointers.length===1)this._panStart.set(e.pageX,e.pageY);else{let t=this._getSecondPointerPosition(e),i=.5*(e.pageX+t.x),r=.5*(e.pageY+t.y);this._panStart.set(i,r)}}_handleTouchStartDolly(e){let t=this._getSecondPointerPosition(e),i=e.pageX-t.x,r=e.pageY-t.y,s=Math.sqrt(i*i+r*r);this._dollyStart.set(0,s)}_handleTouchStartDollyPan(e){this.enableZoom&&this._handleTouchStartDolly(e),this.enablePan&&this._handleTouchStartPan(e)}_handleTouchStartDollyRotate(e){this.enableZoom&&this._handleTouchStartDolly(e),this.enableRotate&&this._handleTouchStartRotate(e)}_handleTouchMoveRotate(e){if(this._pointers.length==1)this._rotateEnd.set(e.pageX,e.pageY);else{let i=this._getSecondPointerPosition(e),r=.5*(e.pageX+i.x),s=.5*(e.pageY+i.y);this._rotateEnd.set(r,s)}this._rotateDelta.subVectors(this._rotateEnd,this._rotateStart).multiplyScalar(this.rotateSpeed);let t=this.domElement;this._rotateLeft(ci*this._rotateDelta.x/t.clientHeight),this._rotateUp(ci*this._rotateDelta.y/t.clientHeight),this._rotateStart.copy(this._rotateEnd)}_handleTouchMovePan(e){if(this._pointers.length===1)this._panEnd.set(e.pageX,e.pageY);else{let t=this._getSecondPointerPosition(e),i=.5*(e.pageX+t.x),r=.5*(e.pageY+t.y);this._panEnd.set(i,r)}this._panDelta.subVectors(this._panEnd,this._panStart).multiplyScalar(this.panSpeed),this._pan(this._panDelta.x,this._panDelta.y),this._panStart.copy(this._panEnd)}_handleTouchMoveDolly(e){let t=this._getSecondPointerPosition(e),i=e.pageX-t.x,r=e.pageY-t.y,s=Math.sqrt(i*i+r*r);this._dollyEnd.set(0,s),this._dollyDelta.set(0,Math.pow(this._dollyEnd.y/this._dollyStart.y,this.zoomSpeed)),this._dollyOut(this._dollyDelta.y),this._dollyStart.copy(this._dollyEnd);let o=(e.pageX+t.x)*.5,a=(e.pageY+t.y)*.5;this._updateZoomParameters(o,a)}_handleTouchMoveDollyPan(e){this.enableZoom&&this._handleTouchMoveDolly(e),this.enablePan&&this._handleTouchMovePan(e)}_handleTouchMoveDollyRotate(e){this.enableZoom&&this._handleTouchMoveDolly(e),this.enableRotate&&this._handleTouchMoveRotate(e)}_addPointer(e){this._pointers.push(e.pointerId)}_removePointer(e){delete this._pointerPositions[e.pointerId];for(let t=0;t<this._pointers.length;t++)if(this._pointers[t]==e.pointerId){this._pointers.splice(t,1);return}}_isTrackingPointer(e){for(let t=0;t<this._pointers.length;t++)if(this._pointers[t]==e.pointerId)return!0;return!1}_trackPointer(e){let t=this._pointerPositions[e.pointerId];t===void 0&&(t=new Ke,this._pointerPositions[e.pointerId]=t),t.set(e.pageX,e.pageY)}_getSecondPointerPosition(e){let t=e.pointerId===this._pointers[0]?this._pointers[1]:this._pointers[0];return this._pointerPositions[t]}_customWheelEvent(e){let t=e.deltaMode,i={clientX:e.clientX,clientY:e.clientY,deltaY:e.deltaY};switch(t){case 1:i.deltaY*=16;break;case 2:i.deltaY*=100;break}return e.ctrlKey&&!this._controlActive&&(i.deltaY*=10),i}};function VN(n){this.enabled!==!1&&(this._pointers.length===0&&(this.domElement.setPointerCapture(n.pointerId),this.domElement.ownerDocument.addEventListener("pointermove",this._onPointerMove),this.domElement.ownerDocument.addEventListener("pointerup",this._onPointerUp)),!this._isTrackingPointer(n)&&(this._addPointer(n),n.pointerType==="touch"?this._onTouchStart(n):this._onMouseDown(n),this._cursorStyle==="grab"&&(this.domElement.style.cursor="grabbing")))}function GN(n){this.enabled!==!1&&(n.pointerType==="touch"?this._onTouchMove(n):this._onMouseMove(n))}function zN(n){switch(this._removePointer(n),this._pointers.length){case 0:this.domElement.releasePointerCapture(n.pointerId),this.domElement.ownerDocument.removeEventListener("pointermove",this._onPointerMove),this.domElement.ownerDocument.removeEventListener("pointerup",this._onPointerUp),this.dispatchEvent(Fv),this.state=Nt.NONE,this._cursorStyle==="grab"&&(this.domElement.style.cursor="grab");break;case 1:let e=this._pointers[0],t=this._pointerPositions[e];this._onTouchStart({pointerId:e,pageX:t.x,pageY:t.y});break}}function HN(n){let e;switch(n.button){case 0:e=this.mouseButtons.LEFT;break;case 1:e=this.mouseButtons.MIDDLE;break;case 2:e=this.mouseButtons.RIGHT;break;default:e=-1}switch(e){case _s.DOLLY:if(this.enableZoom===!1)return;this._handleMouseDownDolly(n),this.state=Nt.DOLLY;break;case _s.ROTATE:if(n.ctrlKey||n.metaKey||n.shiftKey){if(this.enablePan===!1)return;this._handleMouseDownPan(n),this.state=Nt.PAN}else{if(this.enableRotate===!1)return;this._handleMouseDownRotate(n),this.state=Nt.ROTATE}break;case _s.PAN:if(n.ctrlKey||n.metaKey||n.shiftKey){if(this.enableRotate===!1)return;this._handleMouseDownRotate(n),this.state=Nt.ROTATE}else{if(this.enablePan===!1)return;this._handleMouseDownPan(n),this.state=Nt.PAN}break;default:this.state=Nt.NONE}this.state!==Nt.NONE&&this.dispatchEvent(Rm)}function WN(n){switch(this.state){case Nt.ROTATE:if(this.enableRotate===!1)return;this._handleMouseMoveRotate(n);break;case Nt.DOLLY:if(this.enableZoom===!1)return;this._handleMouseMoveDolly(n);break;case Nt.PAN:if(this.enablePan===!1)return;this._handleMouseMovePan(n);break}}function XN(n){this.enabled===!1||this.enableZoom===!1||this.state!==Nt.NONE||(n.preventDefault(),this.dispatchEvent(Rm),this._handleMouseWheel(this._customWheelEvent(n)),this.dispatchEvent(Fv))}function YN(n){this.enabled!==!1&&this._handleKeyDown(n)}function ZN(n){switch(this._trackPointer(n),this._pointers.length){case 1:switch(this.touches.ONE){case ys.ROTATE:if(this.enableRotate===!1){this.state=Nt.NONE;break}this._handleTouchStartRotate(n),this.state=Nt.TOUCH_ROTATE;break;case ys.PAN:if(this.enablePan===!1){this.state=Nt.NONE;break}this._handleTouchStartPan(n),this.state=Nt.TOUCH_PAN;break;default:this.state=Nt.NONE}break;case 2:switch(this.touches.TWO){case ys.DOLLY_PAN:if(this.enableZoom===!1&&this.enablePan===!1)return;this._handleTouchStartDollyPan(n),this.state=Nt.TOUCH_DOLLY_PAN;break;case ys.DOLLY_ROTATE:if(this.enableZoom===!1&&this.enableRotate===!1)return;this._handleTouchStartDollyRotate(n),this.state=Nt.TOUCH_DOLLY_ROTATE;break;default:this.state=Nt.NONE}break;default:this.state=Nt.NONE}this.state!==Nt.NONE&&this.dispatchEvent(Rm)}function KN(n){switch(this._trackPointer(n),this.state){case Nt.TOUCH_ROTATE:if(this.enableRotate===!1)return;this._handleTouchMoveRotate(n),this.update();break;case Nt.TOUCH_PAN:if(this.enablePan===!1)return;this._handleTouchMovePan(n),this.update();break;case Nt.TOUCH_DOLLY_PAN:if(this.enableZoom===!1&&this.enablePan===!1)return;this._handleTouchMoveDollyPan(n),this.update();break;case Nt.TOUCH_DOLLY_ROTATE:if(this.enableZoom===!1&&this.enableRotate===!1)return;this._handleTouchMoveDollyRotate(n),this.update();break;default:this.state=Nt.NONE}}function $N(n){this.enabled!==!1&&n.preventDefault()}function qN(n){n.key==="Control"&&(this._controlActive=!0,this.domElement.ownerDocument.addEventListener("keyup",this._interceptControlUp,{passive:!0,capture:!0}))}function JN(n){n.key==="Control"&&(this._controlActive=!1,this.domElement.ownerDocument.removeEventListener("keyup",this._interceptControlUp,{passive:!0,capture:!0}))}function Im(n,e=!1){let t=n[0].index!==null,i=new Set(Object.keys(n[0].attributes)),r=new Set(Object.keys(n[0].morphAttributes)),s={},o={},a=n[0].morphTargetsRelative,l=new Gn;l.morphTargetsRelative=a;let c=0;for(let u=0;u<n.length;++u){let h=n[u],f=0,d=0;if(t!==(h.index!==null))return console.error("THREE.BufferGeometryUtils: .mergeGeometries() failed with geometry at index "+u+". All geometries must have compatible attributes; make sure index attribute exists among all geometries, or in none of them."),null;for(let p in h.attributes){if(!i.has(p))return console.error("THREE.BufferGeometryUtils: .mergeGeometries() failed with geometry at index "+u+'. All geometries must have compatible attributes; make sure "'+p+'" attribute exists among all geometries, or in none of them.'),null;s[p]===void 0&&(s[p]=[]),s[p].push(h.attributes[p]),f++}if(f!==i.size)return console.error("THREE.BufferGeometryUtils: .mergeGeometries() failed with geometry at index "+u+". Make sure all geometries have the same number of attributes."),null;if(a!==h.morphTargetsRelative)return console.error("THREE.BufferGeometryUtils: .mergeGeometries() failed with geometry at index "+u+". .morphTargetsRelative must be consistent throughout all geometries."),null;for(let p in h.morphAttributes){if(!r.has(p))return console.error("THREE.BufferGeometryUtils: .mergeGeometries() failed with geometry at index "+u+".  .morphAttributes must be consistent throughout all geometries."),null;if(h.morphAttributes[p].length!==n[0].morphAttributes[p].length)return console.error("THREE.BufferGeometryUtils: .mergeGeometries() failed with geometry at index "+u+'. All geometries must have the same number of morph targets for the "'+p+'" morph attribute.'),null;o[p]===void 0&&(o[p]=[]),o[p].push(h.morphAttributes[p]),d++}if(d!==r.size)return console.error("THREE.BufferGeometryUtils: .mergeGeometries() failed with geometry at index "+u+". Make sure all geometries have the same number of morph attributes."),null;if(e){let p;if(t)p=h.index.count;else if(h.attributes.position!==void 0)p=h.attributes.position.count;else return console.error("THREE.BufferGeometryUtils: .mergeGeometries() failed with geometry at index "+u+". The geometry must have either an index or a position attribute"),null;l.addGroup(c,p,u),c+=p}}if(t){let u=0,h=[];for(let f=0;f<n.length;++f){let d=n[f].index;for(let p=0;p<d.count;++p)h.push(d.getX(p)+u);u+=n[f].attributes.position.count}l.setIndex(h)}for(let u in s){let h=Uv(s[u]);if(!h)return console.error("THREE.BufferGeometryUtils: .mergeGeometries() failed while trying to merge the "+u+" attribute."),null;l.setAttribute(u,h)}for(let u in o){let h=o[u][0].length;if(h!==0){l.morphAttributes=l.morphAttributes||{},l.morphAttributes[u]=[];for(let f=0;f<h;++f){let d=[];for(let x=0;x<o[u].length;++x)d.push(o[u][x][f]);let p=Uv(d);if(!p)return console.error("THREE.BufferGeometryUtils: .mergeGeometries() failed while trying to merge the "+u+" morphAttribute."),null;l.morphAttributes[u].push(p)}}}return l}function Uv(n){let e,t,i,r=-1,s=0;for(let c=0;c<n.length;++c){let u=n[c];if(e===void 0&&(e=u.array.constructor),e!==u.array.constructor)return console.error("THREE.BufferGeometryUtils: .mergeAttributes() failed. BufferAttribute.array must be of consistent array types across matching attributes."),null;if(t===void 0&&(t=u.itemSize),t!==u.itemSize)return console.error("THREE.BufferGeometryUtils: .mergeAttributes() failed. BufferAttribute.itemSize must be consistent across matching attributes."),null;if(i===void 0&&(i=u.normalized),i!==u.normalized)return console.error("THREE.BufferGeometryUtils: .mergeAttributes() failed. BufferAttribute.normalized must be consistent across matching attributes."),null;if(r===-1&&(r=u.gpuType),r!==u.gpuType)return console.error("THREE.BufferGeometryUtils: .mergeAttributes() failed. BufferAttribute.gpuType must be consistent across matching attributes."),null;s+=u.count*t}let o=new e(s),a=new kn(o,t,i),l=0;for(let c=0;c<n.length;++c){let u=n[c];if(u.isInterleavedBufferAttribute){let h=l/t;for(let f=0,d=u.count;f<d;f++)for(let p=0;p<t;p++){let x=u.getComponent(f,p);a.setComponent(f+h,p,x)}}else o.set(u.array,l);l+=u.count*t}return r!==void 0&&(a.gpuType=r),a}function Bv(n,e=1e-4){e=Math.max(e,Number.EPSILON);let t={},i=n.getIndex(),r=n.getAttribute("position"),s=i?i.count:r.count,o=0,a=Object.keys(n.attributes),l=[],c=new Map,u=[],h=["getX","getY","getZ","getW"],f=e*.5,d=Math.log10(1/e),p=Math.pow(10,d),x=f*p;for(let g=0;g<s;g++){let b=i?i.getX(g):g,T="";for(let v=0,R=a.length;v<R;v++){let A=a[v],_=n.getAttribute(A),E=_.itemSize;for(let F=0;F<E;F++)T+=`${Math.trunc(_[h[F]](b)*p+x)},`}T in t?u.push(t[T]):(l.push(b),t[T]=o,u.push(o),o++)}let m=n.clone();for(let g in n.attributes)m.setAttribute(g,Ov(n.attributes[g],l,c));for(let g in n.morphAttributes)m.morphAttributes[g]=n.morphAttributes[g].map(b=>Ov(b,l,c));return m.setIndex(u),m}function Ov(n,e,t=new Map){let i=n.isInterleavedBufferAttribute,r=i?n.data:n,s=i?r.stride:n.itemSize,o=i?t.get(r):void 0;if(o===void 0){let l=new r.array.constructor(e.length*s);for(let c=0;c<e.length;c++)for(let u=0;u<s;u++)l[c*s+u]=r.array[e[c]*s+u];o=i?new r.constructor(l,s,r.meshPerAttribute):new n.constructor(l,n.itemSize,n.normalized,n.meshPerAttribute),o.setUsage(r.usage),i&&t.set(r,o)}let a=i?new n.constructor(o,n.itemSize,n.offset,n.normalized):o;return a.name=n.name,i||(a.gpuType=n.gpuType),a}var jN=.3,QN=.25,eP=2,tP=12;function la(n){let e=n.star;if(e&&e.radius>0&&e.coreRadius>0&&e.spikeBaseRadius>0)return{radius:e.radius,coreRadius:e.coreRadius,spikeBaseRadius:e.spikeBaseRadius};let t=n.config?.shapeRadius||.2;return{radius:t,coreRadius:jN*t,spikeBaseRadius:QN*t}}var nP=[[0,0,-Math.PI/2],[0,0,Math.PI/2],[0,0,0],[0,0,Math.PI],[Math.PI/2,0,0],[-Math.PI/2,0,0]];function iP(n){let e=new qo(1,n).attributes.position,t=new X,i=new X,r=new X,s=new X,o=1;for(let a=0;a<e.count;a+=3)t.fromBufferAttribute(e,a),i.fromBufferAttribute(e,a+1),r.fromBufferAttribute(e,a+2),s.crossVectors(i.sub(t),r.sub(t)).normalize(),o=Math.min(o,Math.abs(s.dot(t)));return o}function kv(n,e=eP,t=tP){let i=2*n.spikeBaseRadius/(1+Math.cos(Math.PI/t)),r=[rP(n,e,i*Math.cos(Math.PI/t))],s=i<=n.coreRadius;for(let[o,a,l]of nP){let c=new pl(i,n.radius,t,1,s);c.deleteAttribute("uv"),c.translate(0,n.radius/2,0),c.applyMatrix4(new Tt().makeRotationFromEuler(new Ji(o,a,l))),r.push(c)}return r}function rP(n,e,t){let i=new qo(2*n.coreRadius/(1+iP(e)),e),r=i.attributes.position.array,s=i.attributes.normal.array,o=(h,f,d)=>{let p=d*r[3*h+f],x=Math.hypot(r[3*h+(f+1)%3],r[3*h+(f+2)%3]);return p>=0&&x<t*(1-p/n.radius)},a=h=>[0,1,2].some(f=>[1,-1].some(d=>[h,h+1,h+2].every(p=>o(p,f,d)))),l=[],c=[];for(let h=0;h<r.length/3;h+=3)a(h)||(l.push(...r.slice(3*h,3*h+9)),c.push(...s.slice(3*h,3*h+9)));let u=new Gn;return u.setAttribute("position",new jt(l,3)),u.setAttribute("normal",new jt(c,3)),Bv(u)}function Vv(n){let e=Im(kv(n));if(!e)throw new Error("star geometry: parts do not merge");return e}var sP=0,oP=6;function Gv(n){let e=Im(kv(n,sP,oP));if(!e)throw new Error("star geometry: parts do not merge");return e}var un={body:new tt(8359587),real:new tt(3129201),deemed:new tt(16731469),touching:new tt(11570519),unaudited:new tt(10849480),dimmed:new tt(2764856),picked:new tt(16777215),separate:new tt(6061306)},Cm={standard:{real:3129201,deemed:16731469,touching:11570519,unaudited:10849480,separate:6061306},"colour-blind":{real:29362,deemed:15113984,touching:5682409,unaudited:15787074,separate:13400487}};function Hv(n){let e=Cm[n];un.real.set(e.real),un.deemed.set(e.deemed),un.touching.set(e.touching),un.unaudited.set(e.unaudited),un.separate.set(e.separate)}var zv=.05,Bl=class{constructor(e){this.canvas=e;this.renderer=new qh({canvas:e,antialias:!1,preserveDrawingBuffer:!0});let t=this.renderer.getContext(),i=t.getExtension("WEBGL_debug_renderer_info"),r=String(i?t.getParameter(i.UNMASKED_RENDERER_WEBGL):t.getParameter(t.RENDERER));this.software=/swiftshader|llvmpipe|software/i.test(r),this.sharp(!1),this.scene.background=new tt(1053720),this.scene.add(new bl(16777215,3158080,2.2));let s=new El(16777215,1.5);s.position.set(1,2,3),this.scene.add(s),this.camera=new ii(40,1.6,zv,1e3),this.controls=new ef(this.camera,e),this.controls.enableDamping=!1;let o=new Gn;o.setAttribute("position",new kn(new Float32Array(0),3)),o.setAttribute("color",new kn(new Float32Array(0),3)),this.links=new $o(o,new Vs({vertexColors:!0,depthTest:!1,transparent:!0,opacity:.9})),this.links.frustumCulled=!1,this.links.renderOrder=1,this.links.visible=!1,this.scene.add(this.links)}canvas;renderer;scene=new ol;camera;controls;mesh=null;peripheral=null;detailRegion=null;farStride=1;farCounts={far:0,drawn:0};poses=new Float32Array(0);bodies=0;radius=0;dirty=!1;homeViewProjection=new Tt;software;home={eye:new X,target:new X};box=null;colours=new Float32Array(0);links;setLinks(e,t){if(this.links.visible=t&&e.length>0,!this.links.visible)return;let i=this.links.geometry,r=i.getAttribute("position"),s=i.getAttribute("color");if(r.count<2*e.length){let u=2*Math.max(e.length,2*r.count/2);r=new kn(new Float32Array(3*u),3),s=new kn(new Float32Array(3*u),3),r.setUsage(ia),s.setUsage(ia),i.setAttribute("position",r),i.setAttribute("color",s)}let o=r.array,a=s.array,l=this.poses,c=0;for(let{a:u,b:h,c:f}of e)if(!(u>=this.bodies||h>=this.bodies))for(let d of[u,h])o[3*c]=l[16*d+12],o[3*c+1]=l[16*d+13],o[3*c+2]=l[16*d+14],a[3*c]=f.r,a[3*c+1]=f.g,a[3*c+2]=f.b,c++;i.setDrawRange(0,c),r.needsUpdate=!0,s.needsUpdate=!0}pickAt(e,t){let i=new Ml;i.setFromCamera(new Ke(2*e-1,1-2*t),this.camera);let r=i.ray.origin,s=i.ray.direction,o=this.poses,a=this.radius*this.radius,l=-1,c=1/0;for(let u=0;u<this.bodies;u++){let h=o[16*u+12]-r.x,f=o[16*u+13]-r.y,d=o[16*u+14]-r.z,p=h*s.x+f*s.y+d*s.z;if(p<=0)continue;let x=h*h+f*f+d*d-p*p;if(x>a)continue;let m=p-Math.sqrt(a-x);m<c&&m>this.camera.near&&(c=m,l=u)}return l}bodyOnScreen(e){if(e<0||e>=this.bodies)return null;let t=this.poses;return this.toScreen([t[16*e+12],t[16*e+13],t[16*e+14]])}eccentricities(e,t,i,r,s){let o=this.poses,a=this.homeViewProjection.elements;for(let l=0;l<this.bodies&&l<s.length;l++){let c=16*l,u=o[c+12],h=o[c+13],f=o[c+14],d=a[3]*u+a[7]*h+a[11]*f+a[15];if(d<=0){s[l]=1/0;continue}let p=((a[0]*u+a[4]*h+a[8]*f+a[12])/d+1)/2-e,x=(1-(a[1]*u+a[5]*h+a[9]*f+a[13])/d)/2-t;s[l]=Math.sqrt((p/i)**2+(x/r)**2)}}load(e){let i=e.config?.bodies??0;for(let u of[this.mesh,this.peripheral])u&&(this.scene.remove(u),u.geometry.dispose(),u.dispose());let r=new _l({color:16777215}),s=u=>{let h=new ul(u,r,i);return h.instanceMatrix.setUsage(ia),h.frustumCulled=!1,h.instanceColor=new hs(new Float32Array(3*i),3),h.instanceColor.setUsage(ia),h.count=0,this.scene.add(h),h};this.mesh=s(Vv(la(e))),this.peripheral=s(Gv(la(e))),this.radius=la(e).radius,this.poses=new Float32Array(16*i),this.colours=new Float32Array(3*i),this.bodies=0;let o=e.volumeOrigin??{x:0,y:0,z:0},a=e.volumeSide;this.box&&this.scene.remove(this.box);let l=new $o(new ml(new ds(a,a,a)),new Vs({color:3819094}));l.position.set(o.x+a/2,o.y+a/2,o.z+a/2),this.box=l,this.scene.add(l);let c=e.camera;c?.eye&&c.target&&(this.home.eye.set(c.eye.x,c.eye.y,c.eye.z),this.home.target.set(c.target.x,c.target.y,c.target.z),this.camera.fov=c.fovYDeg,this.camera.aspect=c.aspect,this.camera.far=10*(a+this.home.eye.distanceTo(this.home.target))),this.resetView()}focusOn(e,t,i,r){let s=T=>new X(i[16*T+12],i[16*T+13],i[16*T+14]),o=s(e),a=s(t),l=o.clone().add(a).multiplyScalar(.5),c=a.clone().sub(o),u=c.length()/2+r,h=c.lengthSq()>0?c.normalize():new X(1,0,0),f=this.home.eye.clone().sub(this.home.target).normalize(),d=f.clone().addScaledVector(h,-f.dot(h));d.lengthSq()<1e-6&&(d=new X(0,1,0).cross(h)),d.lengthSq()<1e-6&&(d=new X(0,0,1)),d.normalize();let p=sa.degToRad(this.camera.fov),x=u/Math.sin(p/2),m=i.length/16,g=d.clone(),b=1/0;for(let T=0;T<24&&b>0;T++){let v=(T%2?-1:1)*Math.ceil(T/2)*(Math.PI/12),R=d.clone().applyAxisAngle(h,v);if(Math.abs(R.y)>.95)continue;let A=l.clone().addScaledVector(R,x),_=0;for(let E=0;E<m;E++){if(E===e||E===t)continue;let F=s(E).sub(A),N=-F.dot(R)/x;if(N<=0||N>=1)continue;F.addScaledVector(R,N*x).length()<r+u*N&&_++}_<b&&(b=_,g=R)}this.camera.position.copy(l).addScaledVector(g,x),this.controls.target.copy(l),this.camera.near=Math.max(.01,x-u-.05*r),this.camera.up.set(0,1,0),this.camera.lookAt(l),this.camera.updateProjectionMatrix(),this.controls.update(),this.focused=!0,this.sharp(!0)}toScreen(e){let t=new X(e[0],e[1],e[2]).project(this.camera);return{x:(t.x+1)/2,y:(1-t.y)/2}}wasOrbited=!1;focused=!1;resetView(){this.focused&&this.sharp(!1),this.focused=!1,this.camera.near=zv,this.camera.position.copy(this.home.eye),this.controls.target.copy(this.home.target),this.camera.up.set(0,1,0),this.camera.lookAt(this.home.target),this.camera.updateProjectionMatrix(),this.controls.update(),this.camera.updateMatrixWorld(),this.homeViewProjection.multiplyMatrices(this.camera.projectionMatrix,this.camera.matrixWorldInverse),this.dirty=!0}orbited(){return this.camera.position.distanceToSquared(this.home.eye)>1e-6||this.controls.target.distanceToSquared(this.home.target)>1e-6}followCamera(e){(this.camera.position.distanceToSquared(e.camera.position)>0||this.controls.target.distanceToSquared(e.controls.target)>0||this.camera.near!==e.camera.near)&&(this.camera.position.copy(e.camera.position),this.camera.quaternion.copy(e.camera.quaternion),this.camera.up.copy(e.camera.up),this.camera.near=e.camera.near,this.controls.target.copy(e.controls.target),this.camera.updateProjectionMatrix(),this.dirty=!0)}matrices(){return this.poses}posesWritten(e){this.bodies=e,this.dirty=!0}commit(){this.dirty&&(this.split(),this.dirty=!1)}setFarStride(e){let t=Math.max(1,Math.floor(e));t!==this.farStride&&(this.farStride=t,this.dirty=!0)}setDetailRegion(e){let t=this.detailRegion;t===e||t&&e&&t.x===e.x&&t.y===e.y&&t.rx===e.rx&&t.ry===e.ry||(this.detailRegion=e,this.dirty=!0)}split(){let e=this.mesh,t=this.peripheral;if(!e?.instanceColor||!t?.instanceColor)return;let i=this.poses,r=this.colours,s=this.homeViewProjection.elements,o=this.orbited()?null:this.detailRegion,a=[e,t].map(h=>({m:h.instanceMatrix.array,c:h.instanceColor.array,n:0})),l=o?this.farStride:1,c=0,u=0;for(let h=0;h<this.bodies;h++){let f=16*h,d=!0;if(o){let m=i[f+12],g=i[f+13],b=i[f+14],T=s[3]*m+s[7]*g+s[11]*b+s[15];if(T<=0)d=!1;else{let v=((s[0]*m+s[4]*g+s[8]*b+s[12])/T+1)/2-o.x,R=(1-(s[1]*m+s[5]*g+s[9]*b+s[13])/T)/2-o.y,A=o.rx+s[0]*this.radius/(2*T),_=o.ry+s[5]*this.radius/(2*T);d=(v/A)**2+(R/_)**2<=1}}if(!d){if(c++,h%l!==0)continue;u++}let p=a[d?0:1],x=16*p.n;for(let m=0;m<16;m++)p.m[x+m]=i[f+m];p.c[3*p.n]=r[3*h],p.c[3*p.n+1]=r[3*h+1],p.c[3*p.n+2]=r[3*h+2],p.n++}this.farCounts.far=c,this.farCounts.drawn=u,[e,t].forEach((h,f)=>{h.count=a[f].n,h.instanceMatrix.needsUpdate=!0,h.instanceColor.needsUpdate=!0})}colour(e,t=!1,i=null){let r=this.colours,{r:s,g:o,b:a}=t?un.dimmed:un.body;for(let c=0;c<r.length;c+=3){let u=i?i(c/3):1;r[c]=s*u,r[c+1]=o*u,r[c+2]=a*u}let l=r.length/3;e((c,u)=>{c<l&&(r[3*c]=u.r,r[3*c+1]=u.g,r[3*c+2]=u.b)}),this.dirty=!0}colourOf(e){return Array.from(this.colours.subarray(3*e,3*e+3))}sharp(e){let t=Math.min(window.devicePixelRatio,2);this.renderer.setPixelRatio(e||!this.software?t:.5)}resize(e,t){this.renderer.setSize(e,t,!1)}render(){this.controls.enabled&&this.controls.update();let e=this.orbited();e!==this.wasOrbited&&(this.wasOrbited=e,this.dirty=!0),this.commit(),this.renderer.render(this.scene,this.camera)}};function Oe(n){let e=document.getElementById(n);if(!e)throw new Error(`page element #${n} is missing`);return e}var nn={connected:!1,lastError:"",framesReceived:0,framesApplied:0,lastIndex:-1,bodies:0,updateMs:[],parseMs:[],frameBytes:0,drawMs:0},Fm=Px(),Oi=lp(window.location.origin,Fm.token),aP=Fm.gazeToken?lp(window.location.origin,Fm.gazeToken):Oi,pt=new Bl(Oe("scene")),Um=new Ua(Oe("overlay")),Pn=null,da=new Hc(Oe("plots"),360),Yr=new Ac(aP,Oe("scene")),of=new Wc,tr=null,Zr=null,nr=null,Kr=!1,ua=null,ca=[],hn={paused:!1,frames:-1,note:""},ui={links:!1,priority:!1,thin:localStorage.getItem("foveal.thin")!=="off",palette:localStorage.getItem("foveal.palette")??"standard"};ui.palette in Cm||(ui.palette="standard");var Wt={body:-1,inspection:null,error:""},kt={on:!1,collider:"off",frames:[]},km=[["off",1,"off"],["round-robin",2,"round-robin, gaze-blind"],["exact",3,"exact"]],Ai={armed:new URLSearchParams(window.location.hash.slice(1)).has("focus"),found:null};window.foveal={stats:nn,view:pt,gaze:Yr,focus:Ai,plots:da,split:kt,loop:hn,picked:Wt,draw:ui,calls:ap,pick:n=>Hm(n),lastFrame:()=>nr,tally:()=>Vl,colours:un,csv:n=>of.csv(n)};function Vm(){let n=Oe("view-box"),e=tr?.camera?.aspect||1.6,t=kt.on?2:1,i=kt.on?44:0,r=Math.max(100,Math.min((n.clientWidth-20*(t-1))/t,(n.clientHeight-i)*e)),s=r/e,o=kt.on?["scene","overlay","scene-blind","overlay-blind"]:["scene","overlay"];for(let a of o){let l=Oe(a);l.style.width=`${r}px`,l.style.height=`${s}px`}for(let a of["caption-gaze","caption-blind"])Oe(a).style.width=`${r}px`;pt.resize(r,s),Um.resize(Math.round(r),Math.round(s)),kt.on&&Pn&&(Pn.view.resize(r,s),Pn.overlay.resize(Math.round(r),Math.round(s)))}function lP(n){let e=km.find(([,t])=>t===n.config?.compare);if(kt.on=!!e&&e[1]!==1,kt.collider=e?e[0]:"off",kt.frames.length=0,Oe("side-blind").hidden=!kt.on,Oe("caption-gaze").hidden=!kt.on,!!kt.on){if(!Pn){let t=new Bl(Oe("scene-blind"));t.controls.enabled=!1,Pn={view:t,overlay:new Ua(Oe("overlay-blind")),tally:null}}Pn.view.load(n),Pn.view.setFarStride(pt.farStride)}}function cP(n,e){let t=n.comparison;if(!Pn||!t)return;let i=Pn.view;i.matrices().set(pt.matrices().subarray(0,16*e)),i.posesWritten(e),i.colour(r=>{Pn.tally=t.collisions?tS(t.collisions,r):null}),i.setDetailRegion(pt.detailRegion),i.commit()}function uP(n,e){let t=kt.frames[kt.frames.length-1],i=t?kt.frames.filter(r=>r.index>t.index-e):[];return i.length?i.reduce((r,s)=>r+s[n],0)/i.length:NaN}function hP(){if(!kt.on)return;let n=kt.frames[kt.frames.length-1],e=i=>n?`true P ${n[i].toFixed(3)} (mean of the last 2 s: ${uP(i,120).toFixed(3)})`:"true P: waiting for frames\u2026",t=tr?.config;Oe("caption-gaze").innerHTML=`<b>${wc(t?.scheduler)}</b>, steered by your gaze (the mouse)
`,Oe("caption-gaze").append(e("gaze")),Oe("caption-blind").innerHTML=`<b>${kt.collider==="exact"?"exact":"round-robin"}</b>, gaze-blind: the same frame, ${kt.collider==="exact"?"every pair resolved":"the same budget"}
`,Oe("caption-blind").append(e("blind"))}window.addEventListener("resize",Vm);function jv(n,e){let t=Oe("status");t.textContent=n,t.className=e}function kl(n){return n instanceof dt?n.code===We.Unauthenticated?`${n.rawMessage} (this server wants a token: open ${window.location.origin}/#token=YOUR_TOKEN)`:n.code===We.PermissionDenied?n.rawMessage.includes("has the `gaze` role")?`${n.rawMessage}. This page was opened with a gaze token: it steers the fixation with the mouse but may not watch. Give it a viewer (or admin) token too: ${window.location.origin}/#token=VIEWER_TOKEN&gaze=GAZE_TOKEN`:`${n.rawMessage} (a gaze token sends the mouse, an admin token changes the scene)`:n.code===We.Unknown?n.rawMessage:`${We[n.code]}: ${n.rawMessage}`:n instanceof Error?n.message:String(n)}function fP(n){nn.framesReceived++;let e=performance.now();for(ca.push(e);ca.length&&ca[0]<e-1e3;)ca.shift();if(Kr)return;let t=performance.now(),i=Gm(n),r=n.fixation;pt.setDetailRegion(r&&Zr?{x:r.x,y:r.y,rx:Zr.rx,ry:Zr.ry}:null),pt.commit();let s=performance.now();if(Yv(nn.updateMs,s-t,300),nn.framesReceived%10===0){let c=ts(Ed,n),u=performance.now();gi(Ed,c),Yv(nn.parseMs,performance.now()-u,60),nn.frameBytes=c.length}kt.on&&cP(n,i);let o=kt.on&&Pn?Pn.tally:null,a=Oe("legend");a.classList.toggle("audited",!!Vl?.audited||!!o?.audited),a.classList.toggle("sampled",(Vl?.unaudited??0)+(o?.unaudited??0)>0),nn.framesApplied++,nn.lastIndex=Number(n.index),nn.bodies=i,nr=n;let l=n.metrics;if(l){let c=tr?.config?.budget?.kind,u=null;if(c?.case==="sphereTests"&&c.value>0n)u=Number(l.sphereTests)/Number(c.value);else if(c?.case==="wallMs"&&c.value>0){let x=n.profile;u=1e3*(x?x.renumberS+x.integrateS+x.broadS+x.prioritiseS+x.narrowS+x.responseS+x.measureS:l.collisionTimeS)/c.value}else c?.case==="exact"&&(u=0);let h=Number(l.candidatePairs),f=n.profile,d=n.comparison?.metrics?.audit,p=n.comparison?.mainAudit;kt.on&&p&&d&&(kt.frames.push({index:Number(n.index),gaze:p.truePerceivedInaccuracy,blind:d.truePerceivedInaccuracy,x:r?.x??NaN,y:r?.y??NaN}),kt.frames.length>600&&kt.frames.shift()),da.push({t:n.simTimeS,collisionMs:1e3*l.collisionTimeS,geometric:l.geometricInaccuracy,perceived:l.perceivedInaccuracy,truePerceived:p?p.truePerceivedInaccuracy:l.audit?l.audit.truePerceivedInaccuracy:null,blindTruePerceived:d?d.truePerceivedInaccuracy:null,budgetUse:u,deemedShare:h?Number(l.deemedAtInterruption)/h:null,fps:ca.length,phasesMs:f?[f.integrateS+f.renumberS,f.broadS,f.prioritiseS,f.narrowS,f.responseS,f.measureS].map(x=>1e3*x):[null,null,null,null,null,null]})}of.push(n)}function Qv(n){let e=n?.budget?.kind.case;return{perceived:n?.audit||(n?.compare??1)!==1?"":`The true P needs the exact answer: tick "audit" (or turn the side by side on) to draw it. The solid line is the server's estimate.`,budget:e==="fractionOfExact"?"Budget used is not drawn under a fraction-of-exact budget (the exact cost is not sent); the share deemed is.":e==="interruptAtZero"?"A zero budget does no sphere test: every candidate pair is deemed.":e==="exact"?"No budget: every pair is resolved, none deemed.":""}}function Gm(n){let e=pt.matrices(),t=0;n.quantisedPoses?t=Ax(n.quantisedPoses,e):n.poses&&(t=Rx(n.poses,e)),pt.posesWritten(t);let i=n.collisions;pt.colour(s=>{i?Vl=tS(i,s):Vl=null;let o=Wt.inspection;if(Wt.body>=0&&o)for(let a of o.pairs)s(a.other,Wv(a.status));Wt.body>=0&&s(Wt.body,un.picked)},!1,ui.priority?dP(n,t):null);let r=[];if(ui.links&&i){Yc(i.real,(o,a)=>r.push({a:o,b:a,c:un.real}));let s=i.deemedTruth.length>0;sp(i,(o,a,l)=>r.push({a:o,b:a,c:eS(l,s)}))}if(Wt.body>=0&&Wt.inspection)for(let s of Wt.inspection.pairs)r.push({a:Wt.body,b:s.other,c:Wv(s.status)});return pt.setLinks(r,r.length>0),t}function eS(n,e){return e?n===2?un.deemed:n===1?un.touching:un.unaudited:un.deemed}var Vl=null;function tS(n,e){let t=n.deemedTruth.length>0,i={real:0,deemed:0,touching:0,unaudited:0,audited:t},r=s=>sp(n,(o,a,l)=>{if(!s(l))return;let c=eS(l,t);!t||l===2?i.deemed++:l===1?i.touching++:i.unaudited++,e(o,c),e(a,c)});return t&&r(s=>s===1),Yc(n.real,(s,o)=>(i.real++,e(s,un.real),e(o,un.real))),t&&r(s=>s===0),r(s=>!t||s===2),i}function Wv(n){return n===3?un.real:n===5?un.deemed:un.separate}var tf=new Float32Array(0);function dP(n,e){let t=n.fixation;return!t||!Zr?null:(tf.length<e&&(tf=new Float32Array(e)),pt.eccentricities(t.x,t.y,Zr.rx,Zr.ry,tf),i=>{let r=i<e?tf[i]:1/0;return r<=1?1.6:Math.max(.2,Math.exp(-(r-1)/2))})}var Xv=new Xc,ha=null,Gl=null;async function nS(){if(ha?.abort(),Gl=null,!Ai.armed)return;let n=new AbortController;ha=n,Xv.reset();try{let e=Oi.watchFrames({everyK:1,includePoses:!0,quantisedPoses:!1,includeCollisions:!0},{signal:n.signal});for await(let t of e){if(!Ai.armed)break;let i=[];t.collisions&&Yc(t.collisions.real,(s,o)=>i.push([s,o]));let r=Xv.next(Number(t.index),t.simTimeS,i);if(r.length){Gl={f:t,pair:r[0]},iS();break}}}catch{}finally{n.abort(),ha===n&&(ha=null)}}function iS(){let n=Gl;if(!n||!tr||n.f.poses?.bodies!==tr.config?.bodies)return;Gl=null;let[e,t]=n.pair,i=Gm(n.f);nn.bodies=i,nr=n.f;let r=pt.matrices(),s=la(tr);if(e>=i||t>=i)return;let{gap:o,ends:a}=Mx(s,{m:r,o:16*e},{m:r,o:16*t}),l=c=>[r[16*c+12],r[16*c+13],r[16*c+14]];Ai.found={pair:[e,t],frame:Number(n.f.index),simTimeS:n.f.simTimeS,truth:Tc(tr.config?.truth),radius:s.radius,gap:o,centres:[l(e),l(t)],ends:a},Ai.armed=!1,pt.focusOn(e,t,r.subarray(0,16*i),s.radius),pt.colour(c=>(c(e,un.real),c(t,un.real)),!0),fa(!0)}function pP(n){let e=n.gap/n.radius;return[`first contact at t = ${n.simTimeS.toFixed(3)} s: bodies ${n.pair[0]} and ${n.pair[1]} (the others dimmed)`,`truth ${n.truth}: a real collision; the drawn stars `+(e>.005?`are ${e.toFixed(2)}R apart`:e<-.005?`touch (overlap ${(-e).toFixed(2)}R)`:"touch")]}function rS(n){Ai.armed=n,n?(Ai.found=null,Kr&&fa(!1),pt.resetView(),nS()):ha?.abort()}function Yv(n,e,t){n.push(e),n.length>t&&n.shift()}function Zv(n){if(!n.length)return NaN;let e=[...n].sort((t,i)=>t-i);return e[Math.floor(e.length/2)]}var sS=new As;async function mP(){let n=await Oi.getScene({});sS.succeed(),tr=n,pt.load(n),lP(n);let e=n.config;Zr=e?.display?Y_(e.display,e.eccentricityThresholdDeg):null,oS(e);let t=Oe("truth");t.textContent=`truth: ${Tc(e?.truth)}`,t.title=z_(e?.truth),da.clear(),da.setNotes(Qv(e)),Vm(),nn.connected=!0,nn.lastError="",jv(`connected to ${window.location.host}: ${e?.bodies??0} bodies${pt.software?" (software WebGL: every 6th frame, drawn at 10 fps)":""}`,"ok"),ua=new AbortController,Gl?iS():Ai.armed&&!ha&&nS();let i=Oi.watchFrames({everyK:pt.software?6:1,includePoses:!0,quantisedPoses:!0,includeCollisions:!0},{signal:ua.signal});try{for await(let r of i)fP(r)}catch(r){if(ua.signal.aborted)return;throw r}if(!ua.signal.aborted)throw new Error("the server ended the frame stream (shutting down?)")}async function gP(){for(;;)try{await mP()}catch(n){nn.connected=!1,nn.lastError=kl(n),Oe("truth").textContent="";let e=sS.fail(),t=n instanceof dt&&(n.code===We.Unauthenticated||n.code===We.PermissionDenied),i=`Retrying in ${(e/1e3).toFixed(1)} s\u2026`;jv(t?`foveal-server at ${window.location.host} refused the page: ${nn.lastError}. ${i}`:`cannot reach foveal-server at ${window.location.host}: ${nn.lastError}. ${i}`,"error"),await new Promise(r=>setTimeout(r,e))}}var rf=Oe("scheduler");for(let[n]of Mc)rf.add(new Option(n,n));var sf=Oe("truth-select");for(let[n]of Fa)sf.add(new Option(n,n));function oS(n,e=!1){if(!n)return;let t=(i,r)=>{let s=Oe(i);(e||document.activeElement!==s)&&(s.value=r)};t("scheduler",wc(n.scheduler)),t("truth-select",Tc(n.truth)),t("budget",Md(n.budget)),t("bodies",String(n.bodies)),t("measure-model",Td(n.measureModel)),t("schedule-model",Td(n.scheduleModel)),Oe("audit").checked=n.audit,t("compare",km.find(([,i])=>i===n.compare)?.[0]??"off"),(e||document.activeElement!==Oe("seed"))&&(Oe("seed").placeholder=String(n.seed))}async function vs(n,e){let t=Oe("config-error"),i={},r=s=>{Oe("config-ok").textContent="",t.textContent=`${s} (the control shows the value in force again)`,oS(tr?.config,!0)};try{e(i)}catch(s){r(kl(s));return}t.textContent="applying\u2026";try{let s=await Oi.configure({config:i,updateMask:{paths:[n]}});t.textContent="",Oe("config-ok").textContent=`applied from frame ${s.firstFrameIndex}`,ua?.abort()}catch(s){r(kl(s))}}rf.addEventListener("change",()=>vs("scheduler",n=>{let e=Mc.find(([t])=>t===rf.value);if(!e)throw new Error(`unknown scheduler ${rf.value}`);n.scheduler=e[1]}));sf.addEventListener("change",()=>vs("truth",n=>{let e=Fa.find(([t])=>t===sf.value);if(!e)throw new Error(`unknown truth ${sf.value}`);n.truth=e[1]}));Oe("budget").addEventListener("change",n=>vs("budget",e=>e.budget=H_(n.target.value)));Oe("bodies").addEventListener("change",n=>vs("bodies",e=>{let t=n.target.value,i=Number(t);if(t.trim()===""||!Number.isInteger(i))throw new Error(`bodies N: "${t}" is not a whole number`);if(i<0)throw new Error(`bodies N: ${i} is negative; the scene needs at least 1 body`);e.bodies=i}));Oe("measure-model").addEventListener("change",n=>vs("measure_model",e=>e.measureModel=wd(n.target.value)));Oe("schedule-model").addEventListener("change",n=>vs("schedule_model",e=>e.scheduleModel=wd(n.target.value)));Oe("audit").addEventListener("change",()=>vs("audit",n=>n.audit=Oe("audit").checked));function aS(n){return vs("compare",e=>{let t=km.find(([i])=>i===n);if(!t)throw new Error(`side by side: unknown collider ${n}`);e.compare=t[1]})}Oe("compare").addEventListener("change",n=>{aS(n.target.value)});Oe("mouse-gaze").addEventListener("change",n=>Yr.enabled=n.target.checked);function fa(n){Kr=n,Ys()}function Ys(){Oe("pause").textContent=hn.paused||Kr?"resume":"pause",Oe("loop-note").textContent=hn.note}function af(n,e){hn.paused=n.paused,hn.frames=Number(n.frames),hn.note=e,Ys()}function lf(n,e){return e instanceof dt&&(e.code===We.PermissionDenied||e.code===We.Unauthenticated)?`${n} needs an admin token (${e.rawMessage})`:`${n}: ${kl(e)}`}async function lS(){if(Kr&&!hn.paused){fa(!1);return}try{if(hn.paused)af(await Oi.resume({}),""),fa(!1);else{let n=await Oi.pause({});af(n,`simulation paused after frame ${n.frames-1n}: N or "step" advances one frame`)}}catch(n){hn.paused?hn.note=lf("resuming",n):(fa(!0),hn.note=`${lf("pausing the simulation",n)}: only the view is paused`),Ys()}}async function cS(){try{hn.paused||af(await Oi.pause({}),""),fa(!1);let n=await Oi.step({frames:1});af(n,`simulation paused; stepped to frame ${n.frames-1n}`),Wt.body>=0&&Wm()}catch(n){hn.note=lf("stepping",n),Ys()}}async function _P(){let n=Oe("seed").value.trim(),e;if(n!=="")try{if(e=BigInt(n),e<0n||e>=1n<<64n)throw new Error("out of range")}catch{hn.note=`seed "${n}": use a whole number from 0 to 2^64 - 1 (empty: the seed in force)`,Oe("seed").value="",Ys();return}try{let t=await Oi.restart({seed:e});hn.note=`restarted with seed ${t.applied?.seed} from frame ${t.firstFrameIndex}${hn.paused?" (still paused)":""}`,Oe("seed").value="",ua?.abort()}catch(t){hn.note=lf("restarting",t)}Ys()}Oe("pause").addEventListener("click",()=>{lS()});Oe("step").addEventListener("click",()=>{cS()});Oe("restart").addEventListener("click",()=>{_P()});Oe("reset").addEventListener("click",()=>pt.resetView());Oe("focus").addEventListener("click",()=>rS(!Ai.armed));Oe("help-button").addEventListener("click",()=>cf());Oe("help-close").addEventListener("click",()=>cf(!1));window.addEventListener("keydown",n=>{n.target instanceof HTMLInputElement||n.target instanceof HTMLSelectElement||(n.key==="p"||n.key===" "?(lS(),n.preventDefault()):n.key==="n"||n.key==="."?cS():n.key==="r"?pt.resetView():n.key==="f"?rS(!Ai.armed):n.key==="l"?uf("links",!ui.links):n.key==="e"?uf("priority",!ui.priority):n.key==="s"?aS(kt.on?"off":"round-robin"):n.key==="c"?zm(ui.palette==="standard"?"colour-blind":"standard"):n.key==="?"||n.key==="h"?cf():n.key==="Escape"&&(Oe("help").hidden?Hm(-1):cf(!1)))});function cf(n=Oe("help").hidden){Oe("help").hidden=!n}function hf(){nr&&!(pt.focused&&Kr)&&(Gm(nr),pt.commit())}function uf(n,e){ui[n]=e,Oe(n==="links"?"draw-links":"draw-priority").checked=e,hf()}function uS(n){ui.thin=n,Oe("draw-thin").checked=n,localStorage.setItem("foveal.thin",n?"on":"off"),Bm=0,n||(pt.setFarStride(1),Pn?.view.setFarStride(1))}function zm(n){ui.palette=n,Hv(n),document.body.classList.toggle("colour-blind",n==="colour-blind"),Oe("palette").value=n,localStorage.setItem("foveal.palette",n),hf()}Oe("draw-links").addEventListener("change",n=>uf("links",n.target.checked));Oe("draw-priority").addEventListener("change",n=>uf("priority",n.target.checked));Oe("draw-thin").addEventListener("change",n=>uS(n.target.checked));uS(ui.thin);Oe("palette").addEventListener("change",n=>zm(n.target.value));zm(ui.palette);Oe("csv").addEventListener("click",()=>{let n=Number(Oe("csv-frames").value)||void 0,e=of.csv(n),t=document.createElement("a");t.href=URL.createObjectURL(new Blob([e],{type:"text/csv"})),t.download=`foveal-frames-${of.range(n)}.csv`,t.click(),setTimeout(()=>URL.revokeObjectURL(t.href),1e3)});function Hm(n){Wt.body=n,Wt.inspection=null,Wt.error="",hS(),hf(),n>=0&&Wm()}var Nm=!1;async function Wm(){if(Wt.body<0||Nm)return;let n=Wt.body;Nm=!0;try{let e=await Oi.inspectBody({body:n});Wt.body===n&&(Wt.inspection=e,Wt.error="")}catch(e){Wt.body===n&&(Wt.error=kl(e))}finally{Nm=!1}hS(),hf()}var yP={1:"untested",2:"active",3:"real collision",4:"separate",5:"deemed (budget ran out)"};function hS(){let n=Oe("pick");if(n.hidden=Wt.body<0,Wt.body<0)return;let e=Wt.inspection,t=[`body ${Wt.body}${e?` at frame ${e.frameIndex}: ${e.pairsTotal} candidate pair${e.pairsTotal===1?"":"s"}`:""}  (Esc: unpick)`];if(e&&nr&&e.frameIndex!==nr.index&&t.push(`(the view shows frame ${nr.index}${pt.software?": this page draws every 6th frame; N steps to the latest":""})`),Wt.error)t.push(Wt.error);else if(!e)t.push("asking the server\u2026");else{for(let i of e.pairs)t.push(`  with ${String(i.other).padEnd(6)} ${(yP[i.status]??"?").padEnd(24)} levels ${i.level}/${i.otherLevel}${i.resolvedLevel?` resolved at ${i.resolvedLevel}`:""}  priority ${i.priority>0?i.priority.toPrecision(3):"not ranked"}${i.foveal?"  foveal":""}`);e.pairs.length<e.pairsTotal&&t.push(`  \u2026 and ${e.pairsTotal-e.pairs.length} more`)}Oe("pick-text").textContent=t.join(`
`)}{let n=Oe("scene"),e=null;n.addEventListener("pointerdown",t=>e=t.button===0?{x:t.clientX,y:t.clientY}:null),n.addEventListener("pointerup",t=>{if(!e||Math.hypot(t.clientX-e.x,t.clientY-e.y)>4)return;e=null;let i=n.getBoundingClientRect();Hm(pt.pickAt((t.clientX-i.left)/i.width,(t.clientY-i.top)/i.height))})}function Om(n,e){Oe(n).textContent=e}function Kv(n,e){return n>1?` \xB1 ${e.toFixed(3)} (1 in ${n})`:""}function xP(n){let e=n?.metrics,t=e?.audit??n?.comparison?.mainAudit;if(!e||!t)return[];let i=Number(t.trueFovealFalsePositives),r=Number(t.trueFalsePositives)-i,s=Number(e.fovealPairs),o=Number(e.candidatePairs)-s,a=(l,c)=>c>0?`${(100*l/c).toFixed(1)}%`:"-";return[`wrong guesses (deemed, truly apart): ${a(i,s)} of ${s} pairs within 5\xB0, ${a(r,o)} of ${o} beyond`]}function bP(){let n=nr,e=n?.metrics,t=n?.fixation,i=t?{1:"gaze",2:"no gaze: centre",3:"stale: centre"}[t.source]??"?":"-";Om("readout",e?[`frame ${n?.index}  bodies ${nn.bodies}  ${ca.length} fps`,`pairs ${e.candidatePairs}  real ${e.realCollisions}  deemed ${e.deemedAtInterruption}`,`T ${(1e3*e.collisionTimeS).toFixed(2)} ms  tests ${e.sphereTests}${e.budgetExhausted?" (budget ran out)":""}`,...tr?.config?.budget?.kind.case==="sphereTests"?[`a budget of ${tr.config.budget.kind.value} sphere tests: the same work on any machine, staged (not what a frame's time affords)`]:[],...e.budgetSpentBeforeNarrow?["the budget was spent before the narrow phase: every pair deemed (raise the budget)"]:[],...xP(n),...MP(),`\u0394 ${e.geometricInaccuracy.toFixed(3)}${Kv(e.metricsStride,e.geometricInaccuracySe)}  P ${e.perceivedInaccuracy.toFixed(3)}${Kv(e.metricsStride,e.perceivedInaccuracySe)}${e.audit?`  true P ${e.audit.truePerceivedInaccuracy.toFixed(3)}  false positives ${e.audit.trueFalsePositives}`:""}`,`fixation (${t?.x.toFixed(3)}, ${t?.y.toFixed(3)}) ${i}${Yr.held&&Yr.enabled?" (mouse off the scene: its last position held)":""}`,`decode+update ${Zv(nn.updateMs).toFixed(2)} ms  parse ${Zv(nn.parseMs).toFixed(2)} ms  ${(nn.frameBytes/1024).toFixed(0)} KiB/frame`,`gaze sent ${Yr.accepted}${Yr.lastError?`  (${Yr.lastError})`:""}`].join(`
`):"waiting for frames\u2026"),Oe("orbit-note").hidden=!pt.orbited()||pt.focused&&Kr,Oe("focus").textContent=Ai.armed?"waiting for a first contact\u2026":"focus on a first contact"}var vP=pt.software?100:0,$v=pt.software?60:25,SP=64,Bm=0;function EP(n){if(!ui.thin||n-Bm<1e3)return;Bm=n;let e=pt.farStride,t=e;nn.drawMs>$v&&e<SP?t=2*e:nn.drawMs<$v/3&&e>1&&(t=e/2),t!==e&&(pt.setFarStride(t),Pn?.view.setFarStride(t))}function MP(){let{far:n,drawn:e}=pt.farCounts;return pt.farStride===1||e===n?[]:[`drawn: every body within the foveal region, ${e} of the ${n} beyond (1 in ${pt.farStride}: drawing them all took this browser too long)`]}var qv=0,Jv=0,nf=0,Pm=0,Lm=!1;function fS(n){requestAnimationFrame(fS);let e=n-Pm;if(Lm&&Pm>0){let t=Math.max(0,e-16.666666666666668);nf=.7*nf+.3*2*t,nn.drawMs=nf/2}if(Pm=n,Lm=!1,EP(n),n-Jv>=Math.max(nf,vP)&&(pt.render(),kt.on&&Pn&&(Pn.view.followCamera(pt),Pn.view.render()),Jv=n,Lm=!0),pt.focused&&Kr&&Ai.found){let t=Ai.found,i=t.ends.map(r=>pt.toScreen(r));Um.label(pP(t),t.gap/t.radius>.005?i:[i[0]])}else Um.draw(nr?.fixation,Zr,Yr.enabled?Yr.pointer:null);kt.on&&Pn&&Pn.overlay.draw(nr?.fixation,Zr,null),n-qv>100&&(qv=n,Kr||da.redraw(),bP(),hP())}var Dm=new As(1e3,5e3);async function wP(){if(!(!nn.connected||!Dm.ready())){try{let n=await Oi.getStatus({});Dm.succeed(),n.paused!==hn.paused&&(hn.note=n.paused?`simulation paused after frame ${n.frames-1n}`:""),hn.paused=n.paused,hn.frames=Number(n.frames),Ys(),Om("server",`server: ${n.paused?"paused":`${n.fps.toFixed(1)} fps`}  ${wc(n.config?.scheduler)}  ${Md(n.config?.budget)}  gaze ${n.gazeRateHz.toFixed(0)} Hz  ${n.subscribers} watching`),da.setNotes(Qv(n.config))}catch{Dm.fail(),Om("server","server: unreachable")}Wt.body>=0&&!hn.paused&&Wm()}}Vm();requestAnimationFrame(fS);setInterval(()=>{wP()},1e3);gP();})();
